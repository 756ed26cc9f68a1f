#pragma once
// The names, help texts and ranges of the HierarchyOptions the front ends expose (the CLI's
// `hierarchy` options, the Python keywords of molmesh.hierarchy), written once here; its
// processing and volume options are processing/processing_option_specs.hpp's and
// tetmesh/tetmesh_option_specs.hpp's. Defaults are HierarchyOptions' own; the ranges are what
// HierarchyOptions::validate() accepts (the T0 range is kT0Range, surface's `coarsen` too).
#include <array>

#include "molmesh/core/option_spec.hpp"
#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/processing/processing_option_specs.hpp"

namespace molmesh {

struct HierarchyOptionSpecs {
  OptionSpec t0;
  OptionSpec size_growth;
  OptionSpec renumber;

  // Every entry, in the order above.
  constexpr std::array<const OptionSpec*, 3> all() const { return {&t0, &size_growth, &renumber}; }
};

inline constexpr HierarchyOptionSpecs kHierarchyOptionSpecs{
    // --coarsen: the shared surface layer's name for the same values.
    .t0 = {"t0", "t0",
           "Coarsening thresholds T0 (Eq. 6), one level each, finest first, non-decreasing",
           kT0Range, "--t0,--coarsen"},
    .size_growth = {"size_growth", "size_growth",
                    "Level L grades with `size_factor` times this to the power L, so coarse "
                    "levels coarsen the far field too, not only the surface (1: same far field "
                    "on every level)",
                    OptionRange{kMinSizeGrowth, kMaxSizeGrowth, false}},
    .renumber = {"renumber", "renumber",
                 "Renumber every volume mesh by reverse Cuthill-McKee (default; the permutation "
                 "is stored in /levels/<L>/volume/permutation); off: keep TetGen's numbering",
                 std::nullopt, "!--no-renumber"},
};

}  // namespace molmesh
