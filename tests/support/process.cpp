#include "support/process.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "support/files.hpp"

namespace molmesh::testing {

namespace fs = std::filesystem;

CommandRun run_command(const std::string& shell_command) {
  // Capture files unique per process and call, so parallel tests do not share them.
  static std::atomic<int> calls{0};
  const fs::path base = fs::temp_directory_path() / ("molmesh_run_" + std::to_string(::getpid()) +
                                                     "_" + std::to_string(calls++));
  const fs::path out = base.string() + ".out", err = base.string() + ".err";
  // The shell's own outputs are redirected first, so every part of a compound command is
  // captured and an exec'ed program inherits them.
  const std::string command = "exec > " + shell_quoted(out.string()) + " 2> " +
                              shell_quoted(err.string()) + "; " + shell_command;
  const int status = std::system(command.c_str());
  CommandRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  run.out = slurp(out);
  run.err = slurp(err);
  std::error_code ignored;
  fs::remove(out, ignored);
  fs::remove(err, ignored);
  return run;
}

}  // namespace molmesh::testing
