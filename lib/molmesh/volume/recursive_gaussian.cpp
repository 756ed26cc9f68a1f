#include "molmesh/volume/recursive_gaussian.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

using Complex = std::complex<double>;

// Poles (in the z-plane's reciprocal form d = 1/p) of the 2002 third-order design for
// sigma = 2; other widths raise them to the power 1/q.
const Complex kBasePoleComplex{1.41650, 1.00829};
constexpr double kBasePoleReal = 1.86543;

// Variance of the forward+backward pair whose poles are the base poles scaled by q.
// Each pole contributes d/(d-1)^2 per pass; variances of cascaded filters add.
double pair_variance(double q) {
  const Complex dc = std::pow(kBasePoleComplex, 1.0 / q);
  const double dr = std::pow(kBasePoleReal, 1.0 / q);
  const Complex vc = dc / ((dc - 1.0) * (dc - 1.0));
  const double vr = dr / ((dr - 1.0) * (dr - 1.0));
  return 2.0 * (2.0 * vc.real() + vr);
}

// Variance grows monotonically with q, so bisection on log q finds the exact match; the
// 1995 closed-form q only approximates it and costs accuracy for small sigma.
double solve_scale(double sigma) {
  const double target = sigma * sigma;
  double lo = 1e-3;
  double hi = 10.0 * sigma + 10.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = std::sqrt(lo * hi);
    if (pair_variance(mid) < target) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return std::sqrt(lo * hi);
}

// The backward pass must start as if it had run in from +infinity over the forward pass's
// output, which beyond the end (zero input) is the free response of the recursion. That
// continuation is linear in the last three forward outputs, so the exact start values are a
// 3x3 matrix; we obtain it by running the two recursions on the three unit states until the
// free response has decayed below double precision.
std::array<std::array<double, 3>, 3> triggs_sdika_matrix(double gain,
                                                         const std::array<double, 3>& f,
                                                         double largest_pole) {
  const double decay = std::log(1e-20) / std::log(largest_pole);
  const auto tail = static_cast<std::size_t>(std::ceil(decay)) + 16;
  std::array<std::array<double, 3>, 3> m{};
  std::vector<double> w(tail + 3);
  std::vector<double> y(tail + 3);
  for (int j = 0; j < 3; ++j) {
    // w[0..2] hold w[N-3], w[N-2], w[N-1]; w[3 + t] is w[N + t].
    std::fill(w.begin(), w.end(), 0.0);
    w[static_cast<std::size_t>(2 - j)] = 1.0;
    for (std::size_t t = 3; t < w.size(); ++t) {
      w[t] = f[0] * w[t - 1] + f[1] * w[t - 2] + f[2] * w[t - 3];
    }
    std::fill(y.begin(), y.end(), 0.0);
    for (std::size_t t = w.size(); t-- > 3;) {
      const double y1 = t + 1 < y.size() ? y[t + 1] : 0.0;
      const double y2 = t + 2 < y.size() ? y[t + 2] : 0.0;
      const double y3 = t + 3 < y.size() ? y[t + 3] : 0.0;
      y[t] = gain * w[t] + f[0] * y1 + f[1] * y2 + f[2] * y3;
    }
    for (int i = 0; i < 3; ++i)
      m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          y[static_cast<std::size_t>(3 + i)];
  }
  return m;
}

// Deriche's fit of exp(-x^2 / 2) for x >= 0 (sigma = 1):
//   (1.68 cos(0.6318 x) + 3.735 sin(0.6318 x)) e^(-1.783 x)
//   - (0.6803 cos(1.997 x) + 0.2598 sin(1.997 x)) e^(-1.723 x).
// a cos(w x) + b sin(w x) = Re[(a - i b) e^(i w x)], so each term is one complex pole.
constexpr double kDericheA[2][2] = {{1.68, 3.735}, {-0.6803, -0.2598}};
constexpr double kDericheOmega[2] = {0.6318, 1.997};
constexpr double kDericheDecay[2] = {1.783, 1.723};

RecursiveGaussianCoefficients deriche_coefficients(double sigma) {
  RecursiveGaussianCoefficients c;
  c.design = RecursiveGaussianDesign::kDeriche4;
  c.sigma = sigma;
  Complex sum = 0.0;
  for (int j = 0; j < 2; ++j) {
    c.residue[j] = Complex(kDericheA[j][0], -kDericheA[j][1]);
    c.pole[j] = std::exp(Complex(-kDericheDecay[j], kDericheOmega[j]) / sigma);
    // sum over all n of residue * pole^|n|
    sum += c.residue[j] * (1.0 + c.pole[j]) / (1.0 - c.pole[j]);
  }
  // Unit sum on the sampled lattice (the continuous fit's integral is off by ~1e-4 and by
  // more for small sigma, where sampling matters).
  for (auto& r : c.residue) r /= sum.real();
  return c;
}

// y[n] = sum_k h[k] x[n-k]: the causal part (k >= 0) and the anti-causal part (k < 0) are
// each a pair of first-order complex recursions over the input.
void deriche_lines(const RecursiveGaussianCoefficients& c, double* base, std::size_t n,
                   std::ptrdiff_t stride, std::size_t width, std::vector<Complex>& state,
                   std::vector<double>& out) {
  state.assign(2 * width, Complex(0.0, 0.0));
  out.assign(n * width, 0.0);
  const Complex p0 = c.pole[0];
  const Complex p1 = c.pole[1];
  const Complex r0 = c.residue[0];
  const Complex r1 = c.residue[1];
  Complex* s0 = state.data();
  Complex* s1 = s0 + width;
  for (std::size_t m = 0; m < n; ++m) {
    const double* row = base + static_cast<std::ptrdiff_t>(m) * stride;
    double* o = out.data() + m * width;
    for (std::size_t l = 0; l < width; ++l) {
      s0[l] = row[l] + p0 * s0[l];
      s1[l] = row[l] + p1 * s1[l];
      o[l] = (r0 * s0[l]).real() + (r1 * s1[l]).real();
    }
  }
  std::fill(state.begin(), state.end(), Complex(0.0, 0.0));
  for (std::size_t m = n; m-- > 0;) {
    // s now holds sum_{k>=1} pole^k x[m+k]; x beyond the end is zero, so rest is exact.
    double* row = base + static_cast<std::ptrdiff_t>(m) * stride;
    double* o = out.data() + m * width;
    for (std::size_t l = 0; l < width; ++l) {
      const double x = row[l];
      row[l] = o[l] + (r0 * s0[l]).real() + (r1 * s1[l]).real();
      s0[l] = p0 * (x + s0[l]);
      s1[l] = p1 * (x + s1[l]);
    }
  }
}

// Filters `width` interleaved lines at once: sample m of line l is at
// base[m*stride + l]. Rows of contiguous lines keep the y and z passes cache friendly and
// let the compiler vectorise over l.
void yvv_lines(const RecursiveGaussianCoefficients& c, double* base, std::size_t n,
               std::ptrdiff_t stride, std::size_t width, std::vector<double>& scratch) {
  scratch.assign(3 * width, 0.0);
  double* p1 = scratch.data();
  double* p2 = p1 + width;
  double* p3 = p2 + width;
  const double g = c.gain;
  const double f0 = c.feedback[0];
  const double f1 = c.feedback[1];
  const double f2 = c.feedback[2];
  // One step of the recursion on line m, in either direction: the same update both ways.
  const auto step = [&](std::size_t m) {
    double* row = base + static_cast<std::ptrdiff_t>(m) * stride;
    for (std::size_t l = 0; l < width; ++l) {
      const double v = g * row[l] + f0 * p1[l] + f1 * p2[l] + f2 * p3[l];
      p3[l] = p2[l];
      p2[l] = p1[l];
      p1[l] = v;
      row[l] = v;
    }
  };
  // Forward: the signal is zero before the start, so the recursion starts from rest.
  for (std::size_t m = 0; m < n; ++m) step(m);
  // p1, p2, p3 now hold w[N-1], w[N-2], w[N-3]; replace them by y[N], y[N+1], y[N+2].
  const auto& b = c.boundary;
  for (std::size_t l = 0; l < width; ++l) {
    const double w1 = p1[l];
    const double w2 = p2[l];
    const double w3 = p3[l];
    p1[l] = b[0][0] * w1 + b[0][1] * w2 + b[0][2] * w3;
    p2[l] = b[1][0] * w1 + b[1][1] * w2 + b[1][2] * w3;
    p3[l] = b[2][0] * w1 + b[2][1] * w2 + b[2][2] * w3;
  }
  for (std::size_t m = n; m-- > 0;) step(m);
}

struct LineScratch {
  std::vector<double> real;
  std::vector<Complex> complex;
};

void filter_lines(const RecursiveGaussianCoefficients& c, double* base, std::size_t n,
                  std::ptrdiff_t stride, std::size_t width, LineScratch& scratch) {
  if (c.design == RecursiveGaussianDesign::kDeriche4) {
    deriche_lines(c, base, n, stride, width, scratch.complex, scratch.real);
  } else {
    yvv_lines(c, base, n, stride, width, scratch.real);
  }
}

}  // namespace

RecursiveGaussianCoefficients recursive_gaussian_coefficients(double sigma,
                                                              RecursiveGaussianDesign design) {
  if (!std::isfinite(sigma) || sigma < kMinRecursiveSigma) {
    throw Error("recursive Gaussian: sigma of " + std::to_string(sigma) +
                " grid samples is below the filter's accurate range (>= " +
                std::to_string(kMinRecursiveSigma) +
                "); use a finer grid spacing or the exact blur");
  }
  if (design == RecursiveGaussianDesign::kDeriche4) return deriche_coefficients(sigma);
  const double q = solve_scale(sigma);
  const Complex pc = 1.0 / std::pow(kBasePoleComplex, 1.0 / q);
  const double pr = 1.0 / std::pow(kBasePoleReal, 1.0 / q);
  // Denominator (1 - pc z^-1)(1 - conj(pc) z^-1)(1 - pr z^-1), expanded.
  const double sum_c = 2.0 * pc.real();
  const double prod_c = std::norm(pc);
  RecursiveGaussianCoefficients c;
  c.design = RecursiveGaussianDesign::kYoungVanVliet3;
  c.sigma = sigma;
  c.feedback = {sum_c + pr, -(prod_c + sum_c * pr), prod_c * pr};
  c.gain = 1.0 - c.feedback[0] - c.feedback[1] - c.feedback[2];
  c.boundary = triggs_sdika_matrix(c.gain, c.feedback, std::max(std::abs(pc), pr));
  return c;
}

void recursive_gaussian_line(const RecursiveGaussianCoefficients& c, double* data, std::size_t n,
                             std::ptrdiff_t stride) {
  LineScratch scratch;
  filter_lines(c, data, n, stride, 1, scratch);
}

void recursive_gaussian_filter(Grid& grid, const Vec3& sigma, RecursiveGaussianDesign design) {
  const auto nx = static_cast<std::size_t>(grid.dims[0]);
  const auto ny = static_cast<std::size_t>(grid.dims[1]);
  const auto nz = static_cast<std::size_t>(grid.dims[2]);
  if (grid.values.size() != nx * ny * nz) {
    throw Error("recursive Gaussian: grid has " + std::to_string(grid.values.size()) +
                " values but its dimensions say " + std::to_string(nx * ny * nz));
  }
  if (grid.values.empty()) return;
  double* data = grid.values.data();
  const auto sx = static_cast<std::ptrdiff_t>(nx);
  const auto sxy = static_cast<std::ptrdiff_t>(nx * ny);

  if (sigma.x() > 0.0) {
    const auto c = recursive_gaussian_coefficients(sigma.x() / grid.spacing.x(), design);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ny * nz),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        LineScratch scratch;
                        for (std::size_t line = r.begin(); line != r.end(); ++line) {
                          filter_lines(c, data + line * nx, nx, 1, 1, scratch);
                        }
                      });
  }
  if (sigma.y() > 0.0) {
    const auto c = recursive_gaussian_coefficients(sigma.y() / grid.spacing.y(), design);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nz),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        LineScratch scratch;
                        for (std::size_t k = r.begin(); k != r.end(); ++k) {
                          filter_lines(c, data + k * nx * ny, ny, sx, nx, scratch);
                        }
                      });
  }
  if (sigma.z() > 0.0) {
    const auto c = recursive_gaussian_coefficients(sigma.z() / grid.spacing.z(), design);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ny),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        LineScratch scratch;
                        for (std::size_t j = r.begin(); j != r.end(); ++j) {
                          filter_lines(c, data + j * nx, nz, sxy, nx, scratch);
                        }
                      });
  }
}

}  // namespace molmesh
