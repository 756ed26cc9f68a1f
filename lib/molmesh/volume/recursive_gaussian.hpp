#pragma once
// Separable recursive (IIR) Gaussian filtering of a Grid: the third-order filter of
// Young & van Vliet with the pole placement of Young, van Vliet & van Ginkel (2002), whose
// poles are rescaled so the filter's variance equals sigma^2 exactly, run forward then
// backward along every grid line. The backward pass is started exactly (Triggs & Sdika
// 2006) for a signal that is zero outside the grid, which is what splatted atoms are, so the
// grid boundary adds no error of its own. Cost is O(1) per sample whatever sigma is.
#include <array>
#include <cstddef>

#include "molmesh/volume/grid.hpp"

namespace molmesh {

// Coefficients of one direction's filter for a given sigma (in samples).
//   forward:  w[n] = gain*x[n] + feedback[0]*w[n-1] + feedback[1]*w[n-2] + feedback[2]*w[n-3]
//   backward: y[n] = gain*w[n] + feedback[0]*y[n+1] + feedback[1]*y[n+2] + feedback[2]*y[n+3]
// The pair has unit DC gain and variance sigma^2 (samples^2).
struct RecursiveGaussianCoefficients {
  double sigma = 0.0;
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
RecursiveGaussianCoefficients recursive_gaussian_coefficients(double sigma);

// Filters one line of n samples in place: sample m sits at data[m*stride]. The signal is
// taken as zero outside [0, n). Works for any n >= 1.
void recursive_gaussian_line(const RecursiveGaussianCoefficients& c, double* data, std::size_t n,
                             std::ptrdiff_t stride);

// Convolves the grid in place with a normalised Gaussian of standard deviation sigma (Å,
// per axis; an entry of 0 skips that axis), values outside the grid taken as zero. Lines
// are filtered in parallel (oneTBB); each line's arithmetic is fixed, so the result does
// not depend on the thread count.
void recursive_gaussian_filter(Grid& grid, const Vec3& sigma);

}  // namespace molmesh
