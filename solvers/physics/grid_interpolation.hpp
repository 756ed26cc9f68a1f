#pragma once
// Trilinear interpolation of a regular grid (e.g. an APBS OpenDX potential) at points.
#include <span>
#include <vector>

#include "molmesh/volume/grid.hpp"

namespace molmesh::solvers {

struct InterpolatedField {
  std::vector<double> values;
  int outside = 0;  // points beyond the grid, given the value of the nearest grid point
};

// Points outside the grid are clamped to it (continuous, and the potential there is small
// and smooth for a grid that contains the molecule); the count is returned so callers can
// warn.
InterpolatedField interpolate_trilinear(const Grid& grid, std::span<const Vec3> points);

}  // namespace molmesh::solvers
