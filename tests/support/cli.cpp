#include "support/cli.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace molmesh::testing {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace

namespace {

CliRun run(const std::string& directory, const std::string& shell_prefix, const std::string& args) {
  // Capture files unique per process and call, so parallel tests do not share them.
  static std::atomic<int> calls{0};
  const fs::path base = fs::temp_directory_path() / ("molmesh_cli_" + std::to_string(::getpid()) +
                                                     "_" + std::to_string(calls++));
  const fs::path out = base.string() + ".out", err = base.string() + ".err";
  // exec: the shell is replaced by molmesh, so a signal reaches system()'s status directly.
  std::string command = shell_prefix + " exec " + quoted(MOLMESH_CLI_PATH) + " " + args + " > " +
                        quoted(out.string()) + " 2> " + quoted(err.string());
  if (!directory.empty()) command = "cd " + quoted(directory) + " && " + command;
  const int status = std::system(command.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  run.out = slurp(out);
  run.err = slurp(err);
  std::error_code ignored;
  fs::remove(out, ignored);
  fs::remove(err, ignored);
  return run;
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
