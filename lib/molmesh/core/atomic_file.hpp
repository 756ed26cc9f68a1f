#pragma once
// Outputs are written to a temporary file beside the target and renamed into place only
// when complete, so a failure never leaves a half-written file.
//
// Targets that are not regular files are never replaced by the rename (docs/cli.md,
// "Output paths"): a symbolic link is followed and its target written atomically; a
// character device or FIFO (/dev/null, /dev/full, a pipe) is written in place by the stream
// writers and refused by the path writers (HDF5 needs a regular file); a directory, block
// device or socket is refused. Every failure is an OutputError.
#include <filesystem>
#include <functional>
#include <ostream>

namespace molmesh {

// Calls write(stream) on a temporary file in the target's folder, then renames it to
// `path`. If write throws or the stream fails, the temporary is removed, `path` is left
// as it was, and the error propagates (stream failures become OutputError).
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write, bool binary = false);

// For writers that need a file name (HDF5): write(tmp_path) creates the file at tmp_path,
// which is then renamed to `path`; same guarantees as above.
void write_path_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path&)>& write);

// Installs handlers for SIGINT, SIGTERM and SIGHUP that delete every temporary file the
// functions above have open and then end the process by the same signal (so a shell sees
// exit status 128 + signal: 130 for Ctrl-C, 143 for SIGTERM). For programs (the CLI); the
// library never installs handlers by itself. Also ignores SIGXFSZ, so exceeding a file-size
// limit is a failed write (exit 4), not a kill.
void install_interrupt_cleanup();

}  // namespace molmesh
