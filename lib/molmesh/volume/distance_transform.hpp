#pragma once
// Exact Euclidean distance transform of a set of grid samples (Felzenszwalb & Huttenlocher,
// "Distance Transforms of Sampled Functions", 2012): one lower envelope of parabolas per
// grid line, applied along x, then y, then z. Lines are independent, so they run in
// parallel (oneTBB) and the result does not depend on the thread count.
#include <array>
#include <cstdint>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

struct DistanceTransform {
  std::vector<double> squared_distance;  // to the nearest site (infinity when there is none)
  std::vector<std::int64_t> nearest;     // linear index of that site (-1 when there is none)
};

// `sites[n]` marks the samples the distance is measured to; samples are laid out x fastest
// (Grid::index), `spacing` is the physical sample distance along each axis. Ties between
// equidistant sites go to the one met first along each pass (deterministic).
DistanceTransform euclidean_distance_transform(const std::vector<char>& sites,
                                               const std::array<int, 3>& dims, const Vec3& spacing);

}  // namespace molmesh
