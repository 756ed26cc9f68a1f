#pragma once
// Runs the molmesh command-line program (MOLMESH_CLI_PATH) the way a user does, for the
// tests that check a command end to end, and reports how it ended: robustness tests must tell
// "clear error" from "crash". One runner for every test folder.
#include <string>

namespace molmesh::testing {

struct CliRun {
  int exit_code = -1;  // the program's exit status; -1 if it did not exit normally
  int signal = 0;      // the signal that ended it, 0 when it exited
  std::string out;     // what it wrote to stdout
  std::string err;     // what it wrote to stderr
};

// Runs `molmesh ARGS` through the shell (ARGS is spliced in as written, so quote paths
// with spaces) with stdout and stderr captured.
CliRun run_cli(const std::string& args);

// The same in `directory` (relative paths in ARGS resolve there).
CliRun run_cli_in(const std::string& directory, const std::string& args);

// The same after `shell_prefix` in the same shell (e.g. "ulimit -f 16;").
CliRun run_cli_after(const std::string& shell_prefix, const std::string& args);

}  // namespace molmesh::testing
