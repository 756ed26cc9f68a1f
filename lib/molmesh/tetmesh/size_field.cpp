#include "molmesh/tetmesh/size_field.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "molmesh/tetmesh/outer_sphere.hpp"

namespace molmesh {
namespace {

// Shell radii grow by this factor: linear interpolation of r^1.2 between two shells stays
// within 0.2 % of the law.
constexpr double kShellRatio = 1.25;
// First shell this factor outside the surface's reach, last this factor inside the outer
// sphere (clear of both, so no shell point is close to a facet).
constexpr double kShellClearance = 1.05;
// Icosphere level of a shell (162 points; the field is constant on it).
constexpr int kShellSubdivisions = 2;

}  // namespace

double size_field_radius(double molecule_volume) {
  return std::cbrt(3.0 * std::abs(molecule_volume) / (4.0 * std::numbers::pi));
}

double far_field_size(double r, double radius) {
  return kFarFieldSizeRatio * radius * std::pow(r / radius, kFarFieldSizeExponent);
}

SizePoints far_field_size_points(const Vec3& centre, double reach, double radius,
                                 double outer_radius, double size_factor) {
  SizePoints out;
  const double last = outer_radius / kShellClearance;
  // Each shell turned by its own angle about an axis of no symmetry: concentric icospheres
  // sharing directions (with each other, the outer sphere, an icosphere surface) put four
  // points on a plane through the centre, and TetGen's point location in the background
  // mesh then met flat tetrahedra (an assertion in libtet).
  const Vec3 axis = Vec3(1.0, std::sqrt(2.0), std::sqrt(3.0)).normalized();
  int k = 0;
  for (double r = reach * kShellClearance; r <= last; r *= kShellRatio, ++k) {
    const double h = size_factor * far_field_size(r, radius);
    const Eigen::AngleAxisd turn(std::numbers::phi * (k + 1), axis);
    const SurfaceMesh shell = icosphere(Vec3::Zero(), r, kShellSubdivisions);
    for (const Vec3& p : shell.points) out.points.push_back(centre + turn * p);
    out.sizes.insert(out.sizes.end(), shell.points.size(), h);
  }
  return out;
}

double far_field_tetrahedra(double reach, double radius, double outer_radius, double size_factor) {
  if (!(outer_radius > reach)) return 0.0;
  // ∫ 4πr² kTetrahedraPerCube / h(r)³ dr with h = F κ R^(1 - p) r^p, p = 1.2.
  const double p = kFarFieldSizeExponent;
  const double scale = size_factor * kFarFieldSizeRatio * std::pow(radius, 1.0 - p);
  const double e = 3.0 - 3.0 * p;  // exponent of r in r² / r^(3p), plus one
  return 4.0 * std::numbers::pi * kTetrahedraPerCube / (scale * scale * scale) *
         (std::pow(outer_radius, e) - std::pow(reach, e)) / e;
}

}  // namespace molmesh
