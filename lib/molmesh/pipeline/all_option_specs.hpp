#pragma once
// Every option table of the library in one list, for the front ends that respell the option
// names library messages use (core/error.hpp): the CLI's flags, Python's keywords. A table
// added here is spelled by both.
#include <vector>

#include "molmesh/atoms/atom_option_specs.hpp"
#include "molmesh/core/option_spec.hpp"
#include "molmesh/hierarchy/hierarchy_option_specs.hpp"
#include "molmesh/pipeline/improve_option_specs.hpp"
#include "molmesh/pipeline/surface_option_specs.hpp"
#include "molmesh/processing/processing_option_specs.hpp"
#include "molmesh/tetmesh/tetmesh_option_specs.hpp"

namespace molmesh {

// The entries of every table: tetmesh, surface, processing, improve, atoms, hierarchy, each
// in its own order (where two entries share a member, a front end's first match is the
// tetmesh or surface one).
inline std::vector<const OptionSpec*> all_option_specs() {
  std::vector<const OptionSpec*> specs;
  const auto add = [&specs](const auto& table) {
    for (const OptionSpec* spec : table.all()) specs.push_back(spec);
  };
  add(kTetMeshOptionSpecs);
  add(kSurfaceOptionSpecs);
  add(kProcessingOptionSpecs);
  add(kImproveOptionSpecs);
  add(kAtomOptionSpecs);
  add(kHierarchyOptionSpecs);
  return specs;
}

}  // namespace molmesh
