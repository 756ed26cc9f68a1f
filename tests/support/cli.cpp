#include "support/cli.hpp"

#include "support/files.hpp"

namespace molmesh::testing {
namespace {

CliRun run(const std::string& directory, const std::string& shell_prefix, const std::string& args) {
  // exec: the shell is replaced by molmesh, so a signal reaches the status directly.
  std::string command = shell_prefix + " exec " + shell_quoted(MOLMESH_CLI_PATH) + " " + args;
  if (!directory.empty()) command = "cd " + shell_quoted(directory) + " && " + command;
  return run_command(command);
}

}  // namespace

CliRun run_cli_in(const std::string& directory, const std::string& args) {
  return run(directory, "", args);
}

CliRun run_cli(const std::string& args) { return run("", "", args); }

CliRun run_cli_after(const std::string& shell_prefix, const std::string& args) {
  return run("", shell_prefix, args);
}

}  // namespace molmesh::testing
