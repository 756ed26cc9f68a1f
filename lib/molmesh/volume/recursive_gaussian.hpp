#pragma once
// Separable recursive (IIR) Gaussian filtering of a Grid, O(1) per sample whatever sigma
// is. Two designs:
//  - Deriche (1993), fourth order: the kernel is a sum of two damped cosines, run as a
//    causal and an anti-causal pass over the input that are added. Both passes read the
//    input itself, so starting them at rest is exact for a signal that is zero outside the
//    grid, which is what splatted atoms are. The default: about 20x more accurate.
//  - Young & van Vliet, third order, with the pole placement of Young, van Vliet & van
//    Ginkel (2002) rescaled so the variance is exactly sigma^2; forward then backward over
//    the forward output, the backward pass started exactly (Triggs & Sdika 2006) for the
//    zero extension. Cheaper per sample, but about 1% of the peak off the Gaussian.
// Both are normalised to unit sum; docs/inputs.md compares them.
#include <array>
#include <complex>
#include <cstddef>

#include "molmesh/volume/grid.hpp"

namespace molmesh {

enum class RecursiveGaussianDesign { kDeriche4, kYoungVanVliet3 };

// Coefficients of one direction's filter for a given sigma (in samples).
// Deriche: the impulse response is h[n] = Re sum_j residue[j] * pole[j]^|n|, unit sum.
// Young–van Vliet:
//   forward:  w[n] = gain*x[n] + feedback[0]*w[n-1] + feedback[1]*w[n-2] + feedback[2]*w[n-3]
//   backward: y[n] = gain*w[n] + feedback[0]*y[n+1] + feedback[1]*y[n+2] + feedback[2]*y[n+3]
// The pair has unit DC gain and variance sigma^2 (samples^2).
struct RecursiveGaussianCoefficients {
  RecursiveGaussianDesign design = RecursiveGaussianDesign::kDeriche4;
  double sigma = 0.0;
  std::array<std::complex<double>, 2> residue{};
  std::array<std::complex<double>, 2> pole{};
  double gain = 0.0;
  std::array<double, 3> feedback{};
  // Triggs–Sdika start of the backward pass for a zero right extension:
  // (y[N], y[N+1], y[N+2]) = boundary * (w[N-1], w[N-2], w[N-3]).
  std::array<std::array<double, 3>, 3> boundary{};
};

// Smallest sigma (samples) the filter is accurate for; below it the three poles cannot
// represent a Gaussian and the caller should sample the kernel directly.
inline constexpr double kMinRecursiveSigma = 0.5;

// Throws molmesh::Error if sigma < kMinRecursiveSigma or is not finite.
RecursiveGaussianCoefficients recursive_gaussian_coefficients(
    double sigma, RecursiveGaussianDesign design = RecursiveGaussianDesign::kDeriche4);

// Filters one line of n samples in place: sample m sits at data[m*stride]. The signal is
// taken as zero outside [0, n). Works for any n >= 1.
void recursive_gaussian_line(const RecursiveGaussianCoefficients& c, double* data, std::size_t n,
                             std::ptrdiff_t stride);

// Convolves the grid in place with a normalised Gaussian of standard deviation sigma (Å,
// per axis; an entry of 0 skips that axis), values outside the grid taken as zero. Lines
// are filtered in parallel (oneTBB); each line's arithmetic is fixed, so the result does
// not depend on the thread count.
void recursive_gaussian_filter(Grid& grid, const Vec3& sigma,
                               RecursiveGaussianDesign design = RecursiveGaussianDesign::kDeriche4);

}  // namespace molmesh
