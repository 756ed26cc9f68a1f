#pragma once
// A multilevel mesh hierarchy in one HDF5 file (layout in docs/formats.md, "Hierarchy
// HDF5"), with XDMF 3 sidecars so ParaView and meshio open every level.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh {

inline constexpr const char* kHierarchyFormatName = "molmesh-hierarchy";
inline constexpr int kHierarchyFormatVersion = 1;

// Writes the whole hierarchy to `path` atomically (temporary file + rename), then the XDMF
// sidecars beside it: <stem>_L<L>_volume.xdmf, <stem>_L<L>_surface.xdmf and the collection
// <stem>.xdmf. Throws OutputError when a file cannot be written.
void write_hierarchy(const std::filesystem::path& path, const Hierarchy& hierarchy);

// Loads a file written by write_hierarchy. Throws InputError when the file is missing, is
// not HDF5, or is not a molmesh hierarchy (wrong format name, newer version, missing data).
Hierarchy read_hierarchy(const std::filesystem::path& path);

// Stores one value per volume vertex of `level` (in the file's vertex order, i.e. after the
// locality renumbering) as /levels/<level>/volume/fields/<name>, replacing a field of the
// same name, and rewrites that level's volume XDMF so ParaView shows it. The file is
// modified in place (copied to a temporary, edited, renamed), so a failure leaves it as it
// was. Throws InputError (not a hierarchy, bad level) or Error (wrong number of values).
void write_point_field(const std::filesystem::path& h5, int level, const std::string& name,
                       std::span<const double> values);

// One named field for write_point_fields; `values` is borrowed, not copied.
struct PointFieldView {
  std::string name;
  std::span<const double> values;
};

// Stores several fields of `level` as write_point_field does, with one rewrite of the file:
// all of them or, when any is invalid (name, length) or the write fails, none.
void write_point_fields(const std::filesystem::path& h5, int level,
                        std::span<const PointFieldView> fields);

// Reads a field written by write_point_field; throws InputError when it is absent.
std::vector<double> read_point_field(const std::filesystem::path& h5, int level,
                                     const std::string& name);

// Names of the point fields stored for `level` (sorted).
std::vector<std::string> point_field_names(const std::filesystem::path& h5, int level);

}  // namespace molmesh
