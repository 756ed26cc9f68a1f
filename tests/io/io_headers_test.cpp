// Every io header in one translation unit. Two headers that define the same name would
// not compile here; in separate files they compile and link, and the program then mixes
// the two layouts (an ODR violation: molmesh::PointField was once both vtu.hpp's owning
// field and hierarchy_hdf5.hpp's borrowed one, and `molmesh solve` freed the solver's
// vector through the wrong destructor; ASan: alloc-dealloc-mismatch). When an io header is
// added, add it here (all but the io library's internal HDF5 headers, hdf5_file.hpp and the
// two that include it, which need libhdf5's own headers).
#include <gtest/gtest.h>

#include <type_traits>

#include "molmesh/io/atoms_pqr.hpp"
#include "molmesh/io/atoms_structure.hpp"
#include "molmesh/io/gmsh.hpp"
#include "molmesh/io/hierarchy_export.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/hierarchy_validate.hpp"
#include "molmesh/io/hierarchy_xdmf.hpp"
#include "molmesh/io/mcsf.hpp"
#include "molmesh/io/mesh_obj.hpp"
#include "molmesh/io/mesh_off.hpp"
#include "molmesh/io/mesh_ply.hpp"
#include "molmesh/io/mesh_stl.hpp"
#include "molmesh/io/msms.hpp"
#include "molmesh/io/pdb_records.hpp"
#include "molmesh/io/radius_table.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/sha256.hpp"
#include "molmesh/io/sparse_matrix_io.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/text_input.hpp"
#include "molmesh/io/text_output.hpp"
#include "molmesh/io/volume_dx.hpp"
#include "molmesh/io/volume_io.hpp"
#include "molmesh/io/volume_mesh_io.hpp"
#include "molmesh/io/volume_mrc.hpp"
#include "molmesh/io/vtu.hpp"
#include "molmesh/io/xdmf.hpp"

namespace molmesh {
namespace {

TEST(IoHeaders, OwningAndBorrowedPointFieldsAreDistinctTypes) {
  static_assert(!std::is_same_v<PointField, PointFieldView>);
  const std::vector<double> values{1.0, 2.0};
  const PointField owning{"u", values};
  const PointFieldView borrowed{owning.name, owning.values};
  EXPECT_EQ(borrowed.values.data(), owning.values.data());
  EXPECT_NE(owning.values.data(), values.data());
}

}  // namespace
}  // namespace molmesh
