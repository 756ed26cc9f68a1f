#pragma once
// What read_hierarchy checks before it hands a hierarchy out: contents a solver would
// trust. Sizes agree, values are finite, markers are ones the mesher writes (markers.hpp),
// permutations are permutations, CSR arrays are consistent. A damaged file must be refused
// here rather than produce garbage or crash later. Each check throws hdf5::H5Failure with
// the dataset's path; the reader turns it into an InputError naming the file. Internal to
// io_hierarchy.
#include <cstdint>
#include <string>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh::hierarchy_file {

// One level as read from the group `base` (/levels/<L>).
void validate_level(const HierarchyLevel& level, const std::string& base);

// The CSR arrays of the group `group_path`, before they are viewed as a matrix: the shape,
// indptr from 0 to nnz and non-decreasing, columns in range.
void validate_csr(const std::string& group_path, const std::vector<std::int64_t>& shape,
                  const std::vector<double>& data, const std::vector<int>& indices,
                  const std::vector<std::int64_t>& indptr);

// The transfer between `fine_index` and fine_index + 1 (group `base`): matrix shapes match
// the level sizes, weights are finite, the coarse surface's provenance indexes fine
// vertices.
void validate_transfer(const LevelTransfer& transfer, const HierarchyLevel& fine_level,
                       const HierarchyLevel& coarse_level, int fine_index, const std::string& base);

}  // namespace molmesh::hierarchy_file
