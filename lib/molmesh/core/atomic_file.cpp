#include "molmesh/core/atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

// --- temporaries a signal handler may delete -------------------------------------------------
// Fixed slots of plain characters: the handler may only call async-signal-safe functions
// (unlink), so it cannot walk a std::vector another thread is resizing. A slot is "ready"
// only while its path is complete; more than kSlots temporaries at once (never the case in
// molmesh) simply go unregistered.
constexpr std::size_t kSlots = 16;
constexpr std::size_t kPathBytes = 4096;
struct Slot {
  std::atomic<bool> taken{false};
  std::atomic<bool> ready{false};
  char path[kPathBytes] = {};
};
std::array<Slot, kSlots> g_slots;

class RegisteredTemporary {
 public:
  explicit RegisteredTemporary(const fs::path& path) {
    const std::string text = path.string();
    if (text.size() >= kPathBytes) return;
    for (auto& slot : g_slots) {
      bool expected = false;
      if (!slot.taken.compare_exchange_strong(expected, true)) continue;
      std::memcpy(slot.path, text.c_str(), text.size() + 1);
      slot.ready.store(true);
      slot_ = &slot;
      return;
    }
  }
  RegisteredTemporary(const RegisteredTemporary&) = delete;
  RegisteredTemporary& operator=(const RegisteredTemporary&) = delete;
  ~RegisteredTemporary() {
    if (!slot_) return;
    slot_->ready.store(false);
    slot_->taken.store(false);
  }

 private:
  Slot* slot_ = nullptr;
};

extern "C" void remove_temporaries_and_die(int signal_number) {
  for (auto& slot : g_slots)
    if (slot.ready.load()) ::unlink(slot.path);
  // Die by the same signal, so the parent sees what happened (128 + N in a shell).
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  ::sigaction(signal_number, &action, nullptr);
  ::raise(signal_number);
}

// --- paths -----------------------------------------------------------------------------------

fs::path temporary_sibling(const fs::path& path) {
  std::random_device entropy;
  std::string name = ".";
  name.append(path.filename().string()).append(".tmp").append(std::to_string(entropy() % 1000000));
  return path.parent_path() / name;
}

void remove_quietly(const fs::path& p) {
  std::error_code ignored;
  fs::remove(p, ignored);
}

// Follows symbolic links (also dangling ones: their target is created) so the rename
// replaces the link's target, never the link.
fs::path follow_links(fs::path path) {
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    const auto status = fs::symlink_status(path, ec);
    if (ec || !fs::is_symlink(status)) return path;
    const fs::path target = fs::read_symlink(path, ec);
    if (ec) return path;
    path = target.is_absolute() ? target : path.parent_path() / target;
  }
  throw OutputError("cannot write " + path.string() + ": too many levels of symbolic links");
}

enum class TargetKind { regular, in_place };

// What kind of file `path` (links followed) is; refuses kinds that must not be written.
TargetKind target_kind(const fs::path& path, const fs::path& given) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status) || fs::is_regular_file(status)) return TargetKind::regular;
  if (fs::is_character_file(status) || fs::is_fifo(status)) return TargetKind::in_place;
  const char* what = fs::is_directory(status)    ? "a directory"
                     : fs::is_block_file(status) ? "a block device"
                     : fs::is_socket(status)     ? "a socket"
                                                 : "not a regular file";
  throw OutputError("cannot write " + given.string() + ": it is " + what);
}

void check_stream(std::ofstream& out, const fs::path& given) {
  out.flush();
  if (out) out.close();
  if (!out) throw OutputError("write failed for " + given.string() + " (disk full?)");
}

}  // namespace

void write_path_atomically(const fs::path& path,
                           const std::function<void(const fs::path&)>& write) {
  const fs::path target = follow_links(path);
  if (target_kind(target, path) == TargetKind::in_place)
    throw OutputError("cannot write " + path.string() +
                      ": it is a device or FIFO, and this format (HDF5) needs a regular file");
  const auto tmp = temporary_sibling(target);
  const RegisteredTemporary registered(tmp);
  try {
    write(tmp);
  } catch (const fs::filesystem_error& e) {
    remove_quietly(tmp);
    throw OutputError("cannot write " + path.string() + ": " + e.code().message());
  } catch (...) {
    remove_quietly(tmp);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    remove_quietly(tmp);
    throw OutputError("cannot write " + path.string() + ": " + ec.message());
  }
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  const auto mode = binary ? std::ios::binary | std::ios::out : std::ios::out;
  const fs::path target = follow_links(path);
  if (target_kind(target, path) == TargetKind::in_place) {
    // Devices and FIFOs are written directly: renaming onto them would replace the node.
    std::ofstream out(target, mode);
    if (!out) throw OutputError("cannot open " + path.string() + " for writing");
    write(out);
    check_stream(out, path);
    return;
  }
  write_path_atomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, mode);
    if (!out) throw OutputError("cannot create " + path.string() + " (is the folder writable?)");
    write(out);
    check_stream(out, path);
  });
}

void install_interrupt_cleanup() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_die;
  sigemptyset(&action.sa_mask);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    // Keep an ignored signal ignored (nohup, background jobs without job control).
    if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN)
      continue;
    ::sigaction(signal_number, &action, nullptr);
  }
  ::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace molmesh
