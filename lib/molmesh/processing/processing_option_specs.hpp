#pragma once
// The names, help texts and ranges of the ProcessingOptions the front ends expose (the
// CLI's processing options of `surface`, `improve`, `tetmesh` and `hierarchy`, the Python
// keywords of molmesh.surface, molmesh.improve and molmesh.hierarchy), written once here.
// Defaults are ProcessingOptions' own. The ranges are what ProcessingOptions::validate()
// accepts (process_surface.cpp), the CLI at parse time and Python's docstrings print.
#include <array>
#include <limits>

#include "molmesh/core/option_spec.hpp"

namespace molmesh {

// The coarsening thresholds T0 of Eq. 6 (ProcessingOptions::t0, HierarchyOptions::t0): each
// front end names and describes them for its command (surface's `coarsen`, improve's and the
// hierarchy's `t0`), all with this range.
inline constexpr OptionRange kT0Range{0.0, std::numeric_limits<double>::infinity(), false};

struct ProcessingOptionSpecs {
  OptionSpec rings;
  OptionSpec alpha;
  OptionSpec beta;
  OptionSpec sweeps;
  OptionSpec feature_weight;
  OptionSpec smooth_iterations;
  OptionSpec flips;
  OptionSpec cleanup_rounds;

  // Every entry, in the order above.
  constexpr std::array<const OptionSpec*, 8> all() const {
    return {&rings, &alpha,         &beta, &sweeps, &feature_weight, &smooth_iterations,
            &flips, &cleanup_rounds};
  }
};

inline constexpr ProcessingOptionSpecs kProcessingOptionSpecs{
    .rings = {"rings", "rings",
              "Neighbourhood (in edge rings) of the local structure tensor that detects "
              "features, for coarsening and quality improvement",
              OptionRange{1.0, 10.0, false}},
    .alpha = {"alpha", "alpha",
              "Exponent of the longest incident edge in Eq. 6 (weight of sparseness)",
              OptionRange{0.0, std::numeric_limits<double>::infinity(), false}},
    .beta = {"beta", "beta",
             "Exponent of lambda2/lambda1 in Eq. 6 (weight of curvature: larger keeps curved "
             "regions denser)",
             OptionRange{0.0, std::numeric_limits<double>::infinity(), false}},
    .sweeps = {"sweeps", "sweeps",
               "Passes of angle-based quality improvement over all vertices per round",
               OptionRange{0.0, 100.0, false}},
    .feature_weight = {"feature_weight", "feature_weight",
                       "How strongly vertices on features are held in place during improvement "
                       "(0: not at all)",
                       OptionRange{0.0, std::numeric_limits<double>::infinity(), false}},
    .smooth_iterations = {"smooth_iterations", "normal_iterations",
                          "Normal-diffusion iterations of the feature-preserving smoothing (0: "
                          "no smoothing)",
                          OptionRange{0.0, 100.0, false}},
    .flips = {"flips", "flips", "Flip edges to raise angles (default); off: vertices move only",
              std::nullopt, "!--no-flips"},
    .cleanup_rounds = {"cleanup_rounds", "cleanup_rounds",
                       "Final rounds of improvement and flips aimed at the worst triangles",
                       OptionRange{0.0, 100.0, false}},
};

}  // namespace molmesh
