#pragma once
// MSMS (Sanner's Molecular Surface program) triangulations: a pair `NAME.vert` +
// `NAME.face`, as in GAMer §4.2. Layout in docs/formats.md.
#include <filesystem>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// `path` may name either file of the pair or the common stem; both files must exist.
// Face indices are 1-based in the file. Per-vertex normals and atom/sphere numbers are not
// kept (the processing recomputes normals). Throws InputError (file:line: what).
SurfaceMesh read_msms(const std::filesystem::path& path);

// Writes NAME.vert and NAME.face (atomically each) from `stem_or_either`; vertex normals
// are area-weighted averages of the face normals, atom numbers 0.
void write_msms(const std::filesystem::path& stem_or_either, const SurfaceMesh& mesh);

// True for .vert and .face paths.
bool is_msms_path(const std::filesystem::path& path);

}  // namespace molmesh
