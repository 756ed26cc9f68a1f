#pragma once
// Moving points back onto a level set of a sampled field: Newton steps along the gradient of
// its tricubic (Catmull-Rom) interpolant. Processing uses it (ProcessingOptions::project) to keep
// vertices on the distance-field surfaces while it relocates and smooths them.
#include <functional>
#include <memory>

#include "molmesh/core/geometry.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh {

// A scalar field and its gradient at a point (the gradient written when the pointer is set),
// e.g. trilinear_value on a grid or GaussianField::value. Must be thread-safe.
using ScalarField = std::function<double(const Vec3&, Vec3*)>;

// The point near p where `field` equals `level`: Newton steps x <- x - (F - level) ∇F / |∇F|²,
// each at most `max_step` long, until a step is shorter than `tolerance` or after
// `max_iterations` steps; p itself when the gradient vanishes.
Vec3 newton_to_level(const ScalarField& field, double level, const Vec3& p, double max_step,
                     double tolerance, int max_iterations = 8);

// Trilinear value and gradient at p (clamped to the grid).
double trilinear_value(const Grid& grid, const Vec3& p, Vec3* gradient = nullptr);

// Tricubic (Catmull-Rom) value and gradient at p: C1, exact for quadratics (clamped to the
// grid; the trilinear value on a grid with fewer than 4 samples along an axis).
double tricubic_value(const Grid& grid, const Vec3& p, Vec3* gradient = nullptr);

// newton_to_level on the tricubic interpolant: steps of at most one cell, to 1e-9 cell.
Vec3 project_to_level(const Grid& grid, double level, const Vec3& p);

// project_to_level bound to a grid it keeps alive.
std::function<Vec3(const Vec3&)> level_set_projection(std::shared_ptr<const Grid> grid,
                                                      double level);

}  // namespace molmesh
