#include "molmesh/volume/fast_blur.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/volume/grid_lattice.hpp"
#include "molmesh/volume/recursive_gaussian.hpp"

namespace molmesh {
namespace {

std::string describe_atom(const Atom& a, std::size_t index) {
  std::ostringstream out;
  out << "atom " << index + 1;
  if (!a.atom_name.empty())
    out << " (" << a.atom_name << ' ' << a.residue_name << ' ' << a.residue_number << ')';
  out << " at (" << a.center.x() << ", " << a.center.y() << ", " << a.center.z() << ")";
  return out.str();
}

void splat(const Atoms& atoms, double kappa, SplatMethod method, Grid& grid) {
  const int nx = grid.dims[0];
  const int ny = grid.dims[1];
  const int nz = grid.dims[2];
  // Serial on purpose: neighbouring atoms hit the same nodes, and a fixed summation order
  // keeps the result bit-identical for any thread count; it is a few adds per atom.
  for (std::size_t a = 0; a < atoms.size(); ++a) {
    const Atom& atom = atoms[a];
    if (!(atom.radius > 0.0)) continue;
    const double weight = std::exp(-kappa * atom.radius * atom.radius);
    const Vec3 u = (atom.center - grid.origin).cwiseQuotient(grid.spacing);
    if (!(u.x() >= 0.0 && u.y() >= 0.0 && u.z() >= 0.0 && u.x() <= nx - 1 && u.y() <= ny - 1 &&
          u.z() <= nz - 1)) {
      throw Error("fast blur: " + describe_atom(atom, a) +
                  " lies outside the grid; enlarge the grid margin");
    }
    if (method == SplatMethod::kNearest) {
      grid.at(static_cast<int>(std::lround(u.x())), static_cast<int>(std::lround(u.y())),
              static_cast<int>(std::lround(u.z()))) += weight;
      continue;
    }
    // The cell's lower corner, clamped so an atom exactly on the far face still has a cell.
    const int i = std::min(static_cast<int>(u.x()), std::max(nx - 2, 0));
    const int j = std::min(static_cast<int>(u.y()), std::max(ny - 2, 0));
    const int k = std::min(static_cast<int>(u.z()), std::max(nz - 2, 0));
    const double fx = u.x() - i;
    const double fy = u.y() - j;
    const double fz = u.z() - k;
    for (int dk = 0; dk < 2; ++dk) {
      const double wz = dk ? fz : 1.0 - fz;
      if (wz == 0.0) continue;
      for (int dj = 0; dj < 2; ++dj) {
        const double wy = dj ? fy : 1.0 - fy;
        if (wy == 0.0) continue;
        for (int di = 0; di < 2; ++di) {
          const double wx = di ? fx : 1.0 - fx;
          if (wx == 0.0) continue;
          grid.at(i + di, j + dj, k + dk) += weight * wx * wy * wz;
        }
      }
    }
  }
}

}  // namespace

double constant_decay_rate(const Atoms& atoms, double blobbyness) {
  if (!(blobbyness < 0.0)) {
    throw Error("fast blur: blobbyness must be negative (got " + std::to_string(blobbyness) + ")");
  }
  double sum = 0.0;
  std::size_t count = 0;
  for (const Atom& a : atoms) {
    if (a.radius > 0.0) {
      sum += a.radius;
      ++count;
    }
  }
  if (count == 0) throw Error("fast blur: no atom has a positive radius");
  const double r_ref = sum / static_cast<double>(count);
  return blobbyness / (r_ref * r_ref);
}

Atoms with_constant_decay(const Atoms& atoms, double kappa) {
  Atoms out = atoms;
  for (Atom& a : out) a.blobbyness = kappa * a.radius * a.radius;
  return out;
}

void fast_blur_onto(const Atoms& atoms, const FastBlurOptions& options, Grid& grid,
                    const Reporter& reporter) {
  const double kappa = options.kappa;
  if (!(kappa < 0.0) || !std::isfinite(kappa)) {
    throw Error("fast blur: the decay rate kappa must be negative (got " + std::to_string(kappa) +
                ")");
  }
  if (grid.dims[0] < 1 || grid.dims[1] < 1 || grid.dims[2] < 1) {
    throw Error("fast blur: the grid is empty");
  }
  reporter.progress("fast blur", 0.0);
  grid.values.assign(grid.size(), 0.0);
  splat(atoms, kappa, options.splat, grid);
  reporter.progress("fast blur", 0.2);

  const double sigma2 = -1.0 / (2.0 * kappa);
  const double widening = !options.compensate_splat_width            ? 0.0
                          : options.splat == SplatMethod::kTrilinear ? 1.0 / 6.0
                                                                     : 1.0 / 12.0;
  Vec3 filter_sigma;
  double scale = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double h = grid.spacing[axis];
    const double s2 = sigma2 - widening * h * h;
    if (!(s2 > 0.0)) {
      throw Error("fast blur: the Gaussian (sigma " + std::to_string(std::sqrt(sigma2)) +
                  " Å) is narrower than the grid spacing can represent; use a finer spacing or "
                  "the exact blur");
    }
    filter_sigma[axis] = std::sqrt(s2);
    // The filter has unit sum; Eq. 2's kernel exp(-d^2/(2 sigma^2)) has integral
    // sqrt(2 pi) sigma per axis, i.e. sqrt(2 pi) sigma / h samples.
    scale *= std::sqrt(2.0 * std::numbers::pi * sigma2) / h;
  }
  recursive_gaussian_filter(grid, filter_sigma, options.design);
  reporter.progress("fast blur", 0.95);
  for (double& v : grid.values) v *= scale;
  reporter.progress("fast blur", 1.0);
}

Grid fast_blur(const Atoms& atoms, const BlurOptions& options, SplatMethod splat_method,
               const Reporter& reporter) {
  const double h = options.spacing;
  if (!(h > 0.0) || !std::isfinite(h)) {
    throw Error("grid spacing must be a positive number of Å (got " + std::to_string(h) + ")");
  }
  if (!(options.isovalue > 0.0) || !std::isfinite(options.isovalue)) {
    throw Error("the isovalue must be positive (got " + std::to_string(options.isovalue) + ")");
  }
  if (options.margin_cells < 0) throw Error("the grid margin must not be negative");
  FastBlurOptions fast;
  fast.kappa = constant_decay_rate(atoms, options.blobbyness);
  fast.splat = splat_method;

  bool per_atom = false;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 hi = Vec3::Constant(std::numeric_limits<double>::lowest());
  for (std::size_t n = 0; n < atoms.size(); ++n) {
    const Atom& atom = atoms[n];
    if (!(atom.radius > 0.0)) continue;
    if (!atom.center.allFinite()) {
      throw Error("atom " + std::to_string(n + 1) + " has a non-finite position");
    }
    per_atom = per_atom || atom.blobbyness.has_value();
    // Eq. 2 alone reaches the isovalue t where d^2 = r^2 + ln(t) / kappa.
    const double d2 = atom.radius * atom.radius + std::log(options.isovalue) / fast.kappa;
    const double reach = std::max(atom.radius, d2 > 0.0 ? std::sqrt(d2) : 0.0);
    lo = lo.cwiseMin(atom.center - Vec3::Constant(reach));
    hi = hi.cwiseMax(atom.center + Vec3::Constant(reach));
  }
  if (per_atom) {
    reporter.warn(
        "the fast blur uses one decay rate for all atoms; per-atom blobbyness is ignored "
        "(use the exact blur to honour it)");
  }

  return sample_enclosing(
      lo, hi, h, options.margin_cells, options.isovalue, options.max_memory_bytes,
      [&](Grid& grid) { fast_blur_onto(atoms, fast, grid, reporter); }, reporter);
}

}  // namespace molmesh
