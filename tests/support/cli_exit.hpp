#pragma once
// Runs the real molmesh CLI and reports how it ended: exit code, or the signal that killed
// it (robustness tests must tell "clear error" from "crash"), with stderr captured.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace molmesh::test {

struct CliExit {
  int code = -1;    // exit code, -1 when killed by a signal
  int signal = 0;   // the signal that ended it, 0 when it exited
  std::string err;  // stderr
};

// `args` is appended to "molmesh -q" by the shell (quote paths with spaces yourself).
// `prefix` runs before it in the same shell (e.g. "ulimit -f 64;").
inline CliExit run_molmesh(const std::string& args, const std::string& prefix = "") {
  const auto err_path = std::filesystem::temp_directory_path() /
                        ("molmesh_cli_err_" + std::to_string(::getpid()) + ".txt");
  // exec: the shell is replaced by molmesh, so a signal reaches system()'s status directly.
  const std::string command = prefix + " exec '" + MOLMESH_CLI_PATH + "' -q " + args +
                              " > /dev/null 2> '" + err_path.string() + "'";
  const int status = std::system(command.c_str());
  CliExit result;
  std::ifstream in(err_path);
  std::stringstream text;
  text << in.rdbuf();
  result.err = text.str();
  std::filesystem::remove(err_path);
  if (WIFEXITED(status)) {
    result.code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
  return result;
}

}  // namespace molmesh::test
