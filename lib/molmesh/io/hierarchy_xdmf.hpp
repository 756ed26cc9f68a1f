#pragma once
// The XDMF 3 sidecars of a hierarchy file (io/xdmf.hpp writes the documents): one per level
// and mesh, <stem>_L<L>_volume.xdmf and <stem>_L<L>_surface.xdmf, and the collection
// <stem>.xdmf, beside the HDF5 file. Internal to io_hierarchy.
#include <filesystem>

namespace molmesh::hierarchy_file {

// Regenerates every XDMF sidecar from what the HDF5 file holds (sizes and fields), so the
// sidecars always describe the file as it is. Throws hdf5::H5Failure, InputError (the file
// is not a hierarchy) or OutputError (a sidecar cannot be written).
void write_sidecars(const std::filesystem::path& h5);

}  // namespace molmesh::hierarchy_file
