#include "molmesh/volume/gaussian_blur.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <mutex>
#include <new>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/volume/grid_lattice.hpp"

namespace molmesh {

double kernel_radius(double radius, double blobbyness, double value) {
  if (!(radius > 0.0) || !(blobbyness < 0.0) || !(value > 0.0)) return 0.0;
  const double s2 = 1.0 + std::log(value) / blobbyness;
  return s2 > 0.0 ? radius * std::sqrt(s2) : 0.0;
}

namespace {

// One atom's truncated, separable kernel restricted to the grid: exp(a d^2) per axis, so
// F's contribution at (i, j, k) is fz[k] * fy[j] * fx[i] (fz carries exp(-B)).
struct AtomKernel {
  Vec3 center;
  double cutoff2 = 0.0;  // squared cutoff distance
  int lo[3] = {0, 0, 0};
  int hi[3] = {-1, -1, -1};           // inclusive; empty when hi < lo on any axis
  std::size_t offset[3] = {0, 0, 0};  // where this atom's factors start in the shared buffer
};

struct Box {
  Vec3 lo, hi;
};

// Samples the blurred field on the grid `grid` (origin, spacing, dims already set).
void accumulate(Grid& grid, const Atoms& atoms, const std::vector<int>& active,
                const std::vector<double>& blob, double cutoff_value, const Reporter& reporter) {
  const double h = grid.spacing.x();
  std::vector<AtomKernel> kernels(active.size());
  std::size_t total = 0;
  for (std::size_t n = 0; n < active.size(); ++n) {
    const Atom& atom = atoms[static_cast<std::size_t>(active[n])];
    AtomKernel& kern = kernels[n];
    kern.center = atom.center;
    const double rc = kernel_radius(atom.radius, blob[n], cutoff_value);
    kern.cutoff2 = rc * rc;
    for (int axis = 0; axis < 3; ++axis) {
      const double c = atom.center[axis] - grid.origin[axis];
      kern.lo[axis] = std::max(0, static_cast<int>(std::ceil((c - rc) / h)));
      kern.hi[axis] = std::min(grid.dims[axis] - 1, static_cast<int>(std::floor((c + rc) / h)));
      kern.offset[axis] = total;
      if (rc > 0.0 && kern.hi[axis] >= kern.lo[axis])
        total += static_cast<std::size_t>(kern.hi[axis] - kern.lo[axis] + 1);
      else
        kern.hi[axis] = kern.lo[axis] - 1;
    }
  }

  std::vector<double> factors(total);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, active.size(), 64), [&](const auto& r) {
    for (std::size_t n = r.begin(); n != r.end(); ++n) {
      const Atom& atom = atoms[static_cast<std::size_t>(active[n])];
      const AtomKernel& kern = kernels[n];
      const double a = blob[n] / (atom.radius * atom.radius);
      for (int axis = 0; axis < 3; ++axis) {
        const double scale = axis == 2 ? std::exp(-blob[n]) : 1.0;
        for (int i = kern.lo[axis]; i <= kern.hi[axis]; ++i) {
          const double d = grid.origin[axis] + i * h - atom.center[axis];
          factors[kern.offset[axis] + static_cast<std::size_t>(i - kern.lo[axis])] =
              scale * std::exp(a * d * d);
        }
      }
    }
  });

  // Atoms touching each z-plane, in input order: each plane is summed by one task in that
  // order, so every sample's sum is the same whatever the thread count.
  const int nz = grid.dims[2];
  std::vector<std::size_t> plane_start(static_cast<std::size_t>(nz) + 1, 0);
  for (const AtomKernel& kern : kernels)
    for (int k = kern.lo[2]; k <= kern.hi[2]; ++k) ++plane_start[static_cast<std::size_t>(k) + 1];
  for (int k = 0; k < nz; ++k) plane_start[k + 1] += plane_start[k];
  std::vector<int> plane_atoms(plane_start.back());
  {
    std::vector<std::size_t> fill(plane_start.begin(), plane_start.end() - 1);
    for (std::size_t n = 0; n < kernels.size(); ++n)
      for (int k = kernels[n].lo[2]; k <= kernels[n].hi[2]; ++k)
        plane_atoms[fill[static_cast<std::size_t>(k)]++] = static_cast<int>(n);
  }

  std::atomic<int> planes_done{0};
  std::mutex report_mutex;
  const int nx = grid.dims[0];
  const int ny = grid.dims[1];
  tbb::parallel_for(tbb::blocked_range<int>(0, nz, 1), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k) {
      double* plane = grid.values.data() + static_cast<std::size_t>(k) * nx * ny;
      for (std::size_t p = plane_start[k]; p < plane_start[k + 1]; ++p) {
        const AtomKernel& kern = kernels[static_cast<std::size_t>(plane_atoms[p])];
        const double* fx = factors.data() + kern.offset[0];
        const double* fy = factors.data() + kern.offset[1];
        const double fz = factors[kern.offset[2] + static_cast<std::size_t>(k - kern.lo[2])];
        const double dz = grid.origin.z() + k * h - kern.center.z();
        const double cx = kern.center.x() - grid.origin.x();
        for (int j = kern.lo[1]; j <= kern.hi[1]; ++j) {
          const double dy = grid.origin.y() + j * h - kern.center.y();
          const double rest = kern.cutoff2 - dy * dy - dz * dz;
          if (rest < 0.0) continue;
          // The cutoff is a sphere, so the truncation error bound is isotropic.
          const double w = std::sqrt(rest);
          const int i0 = std::max(kern.lo[0], static_cast<int>(std::ceil((cx - w) / h)));
          const int i1 = std::min(kern.hi[0], static_cast<int>(std::floor((cx + w) / h)));
          const double row = fz * fy[j - kern.lo[1]];
          double* out = plane + static_cast<std::size_t>(j) * nx;
          for (int i = i0; i <= i1; ++i) out[i] += row * fx[i - kern.lo[0]];
        }
      }
      const int done = ++planes_done;
      std::unique_lock lock(report_mutex, std::try_to_lock);
      if (lock.owns_lock()) reporter.progress("blur", 0.95 * done / nz);
    }
  });
}

}  // namespace

void check_blur_options(const BlurOptions& options) {
  const double h = options.spacing;
  if (!(h > 0.0) || !std::isfinite(h))
    throw Error("grid spacing must be a positive number of Å (got " + std::to_string(h) + ")");
  if (!(options.isovalue > 0.0) || !std::isfinite(options.isovalue))
    throw Error("the isovalue must be positive (got " + std::to_string(options.isovalue) + ")");
  if (!(options.truncation > 0.0 && options.truncation < 1.0))
    throw Error("the kernel truncation must lie in (0, 1) (got " +
                std::to_string(options.truncation) + ")");
  if (options.margin_cells < 0) throw Error("the grid margin must not be negative");
}

std::vector<BlurredAtom> blurred_atoms(const Atoms& atoms, double blobbyness) {
  std::vector<BlurredAtom> out;
  for (std::size_t n = 0; n < atoms.size(); ++n) {
    const Atom& atom = atoms[n];
    if (!(atom.radius > 0.0)) continue;
    const double b = atom.blobbyness.value_or(blobbyness);
    if (!(b < 0.0) || !std::isfinite(b))
      throw Error("blobbyness must be negative (got " + std::to_string(b) + " for atom " +
                  std::to_string(n + 1) + ")");
    if (!atom.center.allFinite())
      throw Error("atom " + std::to_string(n + 1) + " has a non-finite position");
    out.push_back({atom.center, atom.radius, b, n});
  }
  if (out.empty()) throw Error("no atom has a positive radius: nothing to blur");
  return out;
}

Grid blur_atoms(const Atoms& atoms, const BlurOptions& options, const Reporter& reporter) {
  check_blur_options(options);
  const double h = options.spacing;

  std::vector<int> active;
  std::vector<double> blob;
  Box box{Vec3::Constant(std::numeric_limits<double>::max()),
          Vec3::Constant(std::numeric_limits<double>::lowest())};
  for (const BlurredAtom& atom : blurred_atoms(atoms, options.blobbyness)) {
    active.push_back(static_cast<int>(atom.index));
    blob.push_back(atom.blobbyness);
    // Where this atom alone reaches the isovalue; at least its radius, so that even a
    // field made only of overlapping tails starts from a sensible box.
    const double reach =
        std::max(atom.radius, kernel_radius(atom.radius, atom.blobbyness, options.isovalue));
    box.lo = box.lo.cwiseMin(atom.center - Vec3::Constant(reach));
    box.hi = box.hi.cwiseMax(atom.center + Vec3::Constant(reach));
  }

  const double cutoff_value = options.truncation * options.isovalue;
  Grid grid = sample_enclosing(
      box.lo, box.hi, h, options.margin_cells, options.isovalue, options.max_memory_bytes,
      [&](Grid& g) {
        allocate_values(g, 0.0);
        reporter.progress("blur", 0.0);
        accumulate(g, atoms, active, blob, cutoff_value, reporter);
      },
      reporter);
  reporter.progress("blur", 1.0);
  return grid;
}

}  // namespace molmesh
