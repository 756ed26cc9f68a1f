#pragma once
// The command-line options of the surface stage (atom selection, blurring, marching cubes,
// cavities, raw), shared by the surface, tetmesh and hierarchy commands so they are spelled
// and documented once. Processing options are bound here too.
#include <CLI/CLI.hpp>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"

namespace molmesh::cli {

struct SurfaceCliOptions {
  AtomReadOptions atoms;
  SurfacePipelineOptions pipeline;
};

// --radii, --hetatm/--no-hetatm, --waters
void add_atom_options(CLI::App& cmd, AtomReadOptions& options);
// --surface, --probe-radius, --spacing, --blobbyness, --isovalue, --min-cavity-volume, --raw (and
// processing options)
void add_surface_pipeline_options(CLI::App& cmd, SurfacePipelineOptions& options);
// Both of the above.
void add_surface_options(CLI::App& cmd, SurfaceCliOptions& options);

}  // namespace molmesh::cli
