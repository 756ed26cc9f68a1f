#pragma once
// What every subcommand shares: the global flags and the terminal progress renderer.
#include "molmesh/core/reporter.hpp"

namespace molmesh::cli {

struct CliContext {
  bool quiet = false;

  // A Reporter that draws progress on stderr (when it is a terminal: a rewritten line;
  // otherwise one line per stage) and prints warnings; silent for progress with --quiet.
  // Warnings are still printed with --quiet, since they are about the result.
  Reporter reporter() const;
};

// Exit codes, documented in docs/cli.md.
enum ExitCode : int {
  kSuccess = 0,
  kFailure = 1,      // molmesh::Error: the request cannot be carried out
  kUsage = 2,        // bad command line
  kInputError = 3,   // unreadable or malformed input file
  kOutputError = 4,  // an output could not be written
  kInternal = 70,    // a bug: please report
};

}  // namespace molmesh::cli
