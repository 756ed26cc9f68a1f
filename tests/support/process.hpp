#pragma once
// Runs a program through the shell and reports how it ended, with its output captured: the
// one runner behind the CLI runner (support/cli.hpp) and the tests that call Python checkers,
// FETK, APBS or mpirun. Robustness tests must tell "clear error" from "crash", so a signal
// is reported apart from an exit status.
#include <string>

namespace molmesh::testing {

struct CommandRun {
  int exit_code = -1;  // the program's exit status; -1 if it did not exit normally
  int signal = 0;      // the signal that ended it, 0 when it exited
  std::string out;     // what it wrote to stdout
  std::string err;     // what it wrote to stderr

  bool ok() const { return exit_code == 0; }
  // stdout then stderr, for a failure message.
  std::string output() const { return out + err; }
};

// Runs `shell_command` with /bin/sh (spliced in as written: quote paths with spaces), its
// stdout and stderr captured. A program the shell runs as a child that dies of a signal shows
// as exit 128 + N; `exec` the last program ("cd D && exec prog ...") to see the signal itself.
CommandRun run_command(const std::string& shell_command);

}  // namespace molmesh::testing
