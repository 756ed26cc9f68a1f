#include "molmesh/tetmesh/molecule_size.hpp"

#include <algorithm>
#include <cmath>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

template <class GetPoint>
MoleculeExtent extent_of(std::size_t n, GetPoint get) {
  MoleculeExtent e;
  // Sum in a fixed order so the result does not depend on anything but the input.
  for (std::size_t i = 0; i < n; ++i) e.centroid += get(i);
  e.centroid /= static_cast<double>(n);
  double max_sq = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    max_sq = std::max(max_sq, (get(i) - e.centroid).squaredNorm());
  e.size = std::sqrt(max_sq);
  return e;
}

}  // namespace

MoleculeExtent molecule_extent(const Atoms& atoms) {
  if (atoms.empty()) throw Error("cannot size an empty molecule (no atoms)");
  return extent_of(atoms.size(), [&](std::size_t i) -> const Vec3& { return atoms[i].center; });
}

MoleculeExtent molecule_extent(const std::vector<Vec3>& points) {
  if (points.empty()) throw Error("cannot size an empty surface (no points)");
  return extent_of(points.size(), [&](std::size_t i) -> const Vec3& { return points[i]; });
}

}  // namespace molmesh
