#pragma once
// Runs the molmesh command-line program (MOLMESH_CLI_PATH) the way a user does, for the
// tests that check a command end to end, and reports how it ended (support/process.hpp):
// robustness tests must tell "clear error" from "crash". One runner for every test folder.
#include <string>

#include "support/process.hpp"

namespace molmesh::testing {

using CliRun = CommandRun;

// Runs `molmesh ARGS` through the shell (ARGS is spliced in as written, so quote paths
// with spaces) with stdout and stderr captured.
CliRun run_cli(const std::string& args);

// The same in `directory` (relative paths in ARGS resolve there).
CliRun run_cli_in(const std::string& directory, const std::string& args);

// The same after `shell_prefix` in the same shell (e.g. "ulimit -f 16;").
CliRun run_cli_after(const std::string& shell_prefix, const std::string& args);

}  // namespace molmesh::testing
