#pragma once
// Outputs are written to a temporary file beside the target and renamed into place only
// when complete, so a failure never leaves a half-written file.
#include <filesystem>
#include <functional>
#include <ostream>

namespace molmesh {

// Calls write(stream) on a temporary file in the target's folder, then renames it to
// `path`. If write throws or the stream fails, the temporary is removed, `path` is left
// as it was, and the error propagates (stream failures become OutputError).
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write,
                           bool binary = false);

// For writers that need a file name (HDF5): write(tmp_path) creates the file at tmp_path,
// which is then renamed to `path`; same guarantees as above.
void write_path_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path&)>& write);

}  // namespace molmesh
