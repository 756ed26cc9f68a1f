#pragma once
// How far a surface lies from the level set F = level it stands for (issue 13): the
// first-order distance |F(x) - level| / |∇F(x)|, at the vertices and at the triangles'
// centroids (which catches facets that cut through the volume between good vertices).
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/volume/level_set_projection.hpp"

namespace molmesh {

struct LevelSetDistance {
  double vertex_mean = 0.0;  // Å, over the vertices referenced by a triangle
  double vertex_max = 0.0;
  double centroid_mean = 0.0;  // Å, over the triangles
  double centroid_max = 0.0;
};

// |F(x) - level| / |∇F(x)| (infinite where the gradient vanishes off the level set).
double level_set_distance(const ScalarField& field, double level, const Vec3& x);

// Parallel; the means are summed in vertex and triangle order, so the result does not
// depend on the thread count.
LevelSetDistance measure_level_set_distance(const SurfaceMesh& mesh, const ScalarField& field,
                                            double level);

}  // namespace molmesh
