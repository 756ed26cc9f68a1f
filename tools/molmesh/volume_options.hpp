#pragma once
// The command-line options of the volume stage (domain, outer sphere, active site, TetGen
// quality and size bounds), shared by the tetmesh and hierarchy commands: names, help texts
// and ranges are the library's (molmesh/tetmesh/tetmesh_option_specs.hpp, which the Python
// module reads too), the defaults TetMeshOptions' own.
#include <CLI/CLI.hpp>
#include <string>

#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh::cli {

struct VolumeCliOptions {
  std::string domain = domain_name(TetMeshOptions{}.domain);
  TetMeshOptions tet;         // the fields below are its optional ones, as the CLI holds them
  double outer_radius = 0.0;  // Å; 0: from --sphere-ratio
  double max_volume = 0.0;    // Å³; 0: unbounded
  std::string active_site;    // sphere list file; empty: none
};

// --domain, --sphere-ratio, --outer-radius, --sphere-subdivisions, --active-site,
// --max-radius-edge, --min-dihedral, --max-volume, --size-factor. `active_site_help` says
// what the active site does in this command beyond marking faces.
void add_volume_options(CLI::App& cmd, VolumeCliOptions& options,
                        const std::string& active_site_help);

// --tetgen-switches (tetmesh only).
void add_tetgen_switches_option(CLI::App& cmd, std::string& switches);

// The TetMeshOptions the options mean (the active-site file is read here); the memory
// limit comes from the surface layer's --max-memory.
TetMeshOptions volume_options(const VolumeCliOptions& options, double max_memory_bytes);

}  // namespace molmesh::cli
