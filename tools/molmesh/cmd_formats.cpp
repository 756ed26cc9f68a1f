// `molmesh formats`: lists what molmesh reads and writes, so users need not guess.
#include <cstdio>

#include "command_registry.hpp"

namespace molmesh::cli {
namespace {

const CommandRegistration registration{
    "formats", [](CLI::App& app, CliContext&) {
      auto* cmd = app.add_subcommand("formats", "List the file formats molmesh reads and writes");
      cmd->callback([] {
        std::puts(
            "atoms in:    .pqr  .pdb .ent .cif .mmcif (optionally .gz; radii from a table)\n"
            "surfaces:    .off .ply .obj .stl (read and write)\n"
            "volumes:     .dx (OpenDX, APBS layout) .mrc .map .ccp4 (MRC2014/CCP4) (read and "
            "write)\n"
            "spheres:     text, 'x y z radius' per line (keep-spheres, active sites)\n"
            "radii:       text, 'RESNAME ATOMNAME radius' or 'ELEMENT radius' per line (--radii)\n"
            "see docs/formats.md for the complete table");
      });
    }};

}  // namespace
}  // namespace molmesh::cli
