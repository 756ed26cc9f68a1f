// `molmesh formats`: lists what molmesh reads and writes, so users need not guess.
#include "command_registry.hpp"

#include <cstdio>

namespace molmesh::cli {
namespace {

const CommandRegistration registration{"formats", [](CLI::App& app, CliContext&) {
  auto* cmd = app.add_subcommand("formats", "List the file formats molmesh reads and writes");
  cmd->callback([] {
    std::puts(
        "atoms in:    .pqr  .pdb .ent .cif .mmcif (optionally .gz; radii from a table)\n"
        "surfaces:    .off .ply .obj .stl (read and write)\n"
        "see docs/formats.md for the complete table");
  });
}};

}  // namespace
}  // namespace molmesh::cli
