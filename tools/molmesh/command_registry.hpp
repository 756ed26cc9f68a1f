#pragma once
// Each subcommand lives in its own cmd_<name>.cpp and registers itself with a static
// CommandRegistration, so adding a command never touches main.cpp.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "cli_context.hpp"

namespace molmesh::cli {

// add(app, ctx) creates the subcommand on `app` and sets its callback.
using CommandAdder = std::function<void(CLI::App& app, CliContext& ctx)>;

struct CommandRegistration {
  CommandRegistration(std::string name, CommandAdder add);
};

struct RegisteredCommand {
  std::string name;
  CommandAdder add;
};

// Sorted by name, so --help lists commands in a stable order.
std::vector<RegisteredCommand> registered_commands();

}  // namespace molmesh::cli
