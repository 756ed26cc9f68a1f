#pragma once
// TetGen's input: a surface (and an optional outer sphere) as the piecewise linear complex
// tetgenio holds, each facet with its boundary marker (markers.hpp). Internal (TetGen's
// types are not part of molmesh's API): tetrahedralize() and the tests that call TetGen
// directly share it.
#include <tetgen.h>

#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh::detail {

// Fills `in` (empty): the surface's points and triangles first (TetGen keeps their
// indices), then the sphere's; surface facets are kMolecularSurface, or kActiveSite where
// markers::in_active_site says so, sphere facets kOuterSphere. Numbering from 0.
void fill_plc(const SurfaceMesh& surface, const SurfaceMesh& sphere,
              const std::vector<Sphere>& active_site, tetgenio& in);

}  // namespace molmesh::detail
