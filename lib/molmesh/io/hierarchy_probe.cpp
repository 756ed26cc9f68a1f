#include "molmesh/io/hierarchy_probe.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <set>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/io/hierarchy_layout.hpp"

namespace molmesh::hierarchy_file {
namespace {

// libhdf5 1.10 crashes (SIGSEGV in H5A__close from H5Aiterate2) or loops forever on some
// damaged files: 4 bytes changed in the metadata were enough (issue 18). No check of the
// file's structure ahead of libhdf5 can rule that out, so the first read of a file runs in
// a child process: everything a reader here will touch is read there once. If the child
// dies or runs out of time, the file is refused (InputError, exit code 3) and this process
// never hands the file to libhdf5; otherwise the real read repeats what is known to work.
// Costs one extra read of the file (docs/formats.md, "Damaged files").
void read_everything(const std::filesystem::path& path) {
  read_contents(path);
  auto [file, levels] = open_unprobed(path, H5F_ACC_RDONLY);
  for (int level = 0; level < levels; ++level)
    for (const auto& name : field_names(file.get(), level))
      hdf5::read_dataset<double>(file.get(), field_path(level, name), 0);
}

std::string probe_key(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  const auto time = std::filesystem::last_write_time(path, ec).time_since_epoch().count();
  return std::filesystem::absolute(path).string() + "|" + std::to_string(size) + "|" +
         std::to_string(time);
}

}  // namespace

void probe_hierarchy(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string(), "no such file");
  static std::mutex mutex;
  static std::set<std::string> probed;  // files this process has read safely already
  const std::string key = probe_key(path);
  {
    const std::lock_guard lock(mutex);
    if (probed.count(key)) return;
  }
  int channel[2];
  if (::pipe(channel) != 0) throw InputError(path.string(), "cannot start the reader");
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(channel[0]);
    ::close(channel[1]);
    throw InputError(path.string(), "cannot start the reader");
  }
  if (child == 0) {
    ::close(channel[0]);
    // A fault here must end this child with its signal and nothing else: fault handlers
    // inherited from the parent (a sanitizer's, a fuzzer's that saves the input as a crash
    // of the parent, Python's faulthandler) would report the contained libhdf5 fault as the
    // program's own. (Aborts keep their handlers: an abort is our own assertion, not
    // libhdf5 reading bad bytes.)
    for (int fault : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) ::signal(fault, SIG_DFL);
    std::string message;
    int code = 0;
    try {
      read_everything(path);
    } catch (const std::exception& e) {
      message = e.what();
      code = 3;
    }
    if (!message.empty() && ::write(channel[1], message.data(), message.size()) < 0) code = 4;
    ::_exit(code);  // no atexit handlers, no HDF5 shutdown: just the verdict
  }
  ::close(channel[1]);
  // Generous: reading a 100 MB hierarchy takes about a second.
  const double seconds = 60.0 + static_cast<double>(std::filesystem::file_size(path)) / 1e7;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::string message;
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                          deadline - std::chrono::steady_clock::now())
                          .count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd fd{channel[0], POLLIN, 0};
    const int ready = ::poll(&fd, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char buffer[4096];
    const ssize_t n = ::read(channel[0], buffer, sizeof buffer);
    if (n <= 0) break;  // EOF: the child is done
    message.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(channel[0]);
  if (timed_out) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out)
    throw InputError(path.string(), "damaged HDF5 file: reading it did not finish within " +
                                        std::to_string(static_cast<int>(seconds)) + " s");
  if (WIFSIGNALED(status))
    throw InputError(path.string(), "damaged HDF5 file: libhdf5 crashed reading it (signal " +
                                        std::to_string(WTERMSIG(status)) + ")");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    // The child's InputError already starts with the file name.
    const std::string prefix = path.string() + ": ";
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    throw InputError(path.string(), message.empty() ? "damaged HDF5 file" : message);
  }
  const std::lock_guard lock(mutex);
  probed.insert(key);
}

std::pair<hdf5::Handle, int> open_hierarchy(const std::filesystem::path& path, unsigned flags) {
  probe_hierarchy(path);
  return open_unprobed(path, flags);
}

}  // namespace molmesh::hierarchy_file
