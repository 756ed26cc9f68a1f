#pragma once
// The names, help texts and ranges of the ImprovePipelineOptions the front ends expose (the
// CLI's `improve` options, the Python keywords of molmesh.improve), written once here; its
// processing options are processing/processing_option_specs.hpp's. Defaults are
// ImprovePipelineOptions' own. The ranges are what ImprovePipelineOptions::validate()
// accepts, the CLI at parse time and Python's docstrings print.
#include <array>
#include <limits>

#include "molmesh/core/option_spec.hpp"
#include "molmesh/processing/processing_option_specs.hpp"

namespace molmesh {

struct ImproveOptionSpecs {
  OptionSpec t0;
  OptionSpec repair_only;
  OptionSpec merge_tolerance;

  // Every entry, in the order above.
  constexpr std::array<const OptionSpec*, 3> all() const {
    return {&t0, &repair_only, &merge_tolerance};
  }
};

inline constexpr ImproveOptionSpecs kImproveOptionSpecs{
    .t0 = {"t0", "t0",
           "Coarsening thresholds T0 of Eq. 6, one coarsening round each, in order (larger "
           "removes more vertices; features survive better with several small rounds; none: "
           "no coarsening)",
           kT0Range},
    .repair_only = {"repair_only", "repair_only", "Write the repaired mesh without any processing",
                    std::nullopt},
    .merge_tolerance = {"merge_tolerance", "merge_tolerance",
                        "Vertices closer than this (Å) are merged during repair (0: only exact "
                        "duplicates)",
                        OptionRange{0.0, std::numeric_limits<double>::infinity(), false}},
};

}  // namespace molmesh
