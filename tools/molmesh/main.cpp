// molmesh: molecules to simulation-ready meshes. Subcommands register themselves
// (command_registry.hpp); this file only parses, dispatches and maps errors to exit codes.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "cli_context.hpp"
#include "command_registry.hpp"
#include "help_formatter.hpp"
#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/core/malloc_tuning.hpp"
#include "molmesh/core/version.hpp"
#include "option_spelling.hpp"

int main(int argc, char** argv) {
  using namespace molmesh::cli;
  molmesh::keep_freed_memory_for_reuse();
  // Ctrl-C / SIGTERM delete the temporaries of outputs being written (docs/cli.md).
  molmesh::install_interrupt_cleanup();
  CLI::App app{"molmesh: molecules to adaptive surface and tetrahedral meshes (GAMer method)"};
  use_help_formatter(app);
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("molmesh ") + molmesh::version());
  app.fallthrough();  // lets --quiet appear after the subcommand too
  CliContext ctx;
  app.add_flag("-q,--quiet", ctx.quiet, "Do not show progress")->configurable(false);
  for (const auto& command : registered_commands()) command.add(app, ctx);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kSuccess : kUsage;
  } catch (const molmesh::OptionError& e) {
    std::fprintf(stderr, "molmesh: error: %s\n", with_cli_flags(e.what()).c_str());
    return kUsage;
  } catch (const molmesh::InputError& e) {
    std::fprintf(stderr, "molmesh: error: %s\n", with_cli_flags(e.what()).c_str());
    return kInputError;
  } catch (const molmesh::OutputError& e) {
    std::fprintf(stderr, "molmesh: error: %s\n", with_cli_flags(e.what()).c_str());
    return kOutputError;
  } catch (const molmesh::Error& e) {
    std::fprintf(stderr, "molmesh: error: %s\n", with_cli_flags(e.what()).c_str());
    return kFailure;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "molmesh: error: out of memory (try a coarser --spacing)\n");
    return kFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "molmesh: internal error: %s (please report this)\n", e.what());
    return kInternal;
  }
  return kSuccess;
}
