// Outputs that are not plain new files (issue 18, findings 5-7): symbolic links are
// followed, FIFOs and character devices written in place (never replaced by the rename),
// a full disk or file-size limit is exit code 4 with nothing left behind, and SIGINT or
// SIGTERM during a run deletes the temporary being written.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <string>
#include <thread>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), {}));
}

const std::string kFas2 = std::string(MOLMESH_TEST_DATA_DIR) + "/fas2.pqr";
const std::string k1a1p = std::string(MOLMESH_TEST_DATA_DIR) + "/1a1p.pqr";

TEST(OutputPaths, SymlinkIsFollowedNotReplaced) {
  const auto dir = testing::test_dir("link");
  std::ofstream(dir / "target.txt") << "old\n";
  fs::create_symlink("target.txt", dir / "link.txt");
  write_file_atomically(dir / "link.txt", [](std::ostream& o) { o << "new\n"; });
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.txt")));
  EXPECT_EQ(testing::slurp(dir / "target.txt"), "new\n");
  // A dangling link creates its target.
  fs::create_symlink("made.txt", dir / "dangling.txt");
  write_file_atomically(dir / "dangling.txt", [](std::ostream& o) { o << "x"; });
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "dangling.txt")));
  EXPECT_EQ(testing::slurp(dir / "made.txt"), "x");
  fs::remove_all(dir);
}

TEST(OutputPaths, FifoIsWrittenInPlace) {
  const auto dir = testing::test_dir("fifo");
  const fs::path fifo = dir / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = std::async(std::launch::async, [&] { return testing::slurp(fifo); });
  write_file_atomically(fifo, [](std::ostream& o) { o << "through the pipe\n"; });
  EXPECT_EQ(reader.get(), "through the pipe\n");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_EQ(entries(dir), 1u);
  // HDF5 needs a regular file: refused, and the FIFO stays.
  EXPECT_THROW(write_path_atomically(fifo, [](const fs::path&) {}), OutputError);
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  EXPECT_THROW(write_file_atomically(dir, [](std::ostream&) {}), OutputError);
  fs::remove_all(dir);
}

TEST(OutputPaths, DevFullIsExitCode4) {
  // The mesh formats are chosen by extension, so the device is given as the --stats file.
  const auto dir = testing::test_dir("devfull");
  const auto s = testing::run_cli("-q surface " + kFas2 + " --raw -o " + (dir / "s.off").string() +
                                  " --stats /dev/full");
  EXPECT_EQ(s.exit_code, 4) << s.err;
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
  const auto n = testing::run_cli("-q surface " + kFas2 + " --raw -o " + (dir / "t.off").string() +
                                  " --stats /dev/null");
  EXPECT_EQ(n.exit_code, 0) << n.err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  fs::remove_all(dir);
}

TEST(OutputPaths, FileSizeLimitIsExitCode4AndLeavesNothing) {
  // ulimit -f: writes beyond 64 blocks fail (SIGXFSZ is ignored by the CLI).
  const auto dir = testing::test_dir("fsize");
  for (const std::string& command :
       {"surface " + kFas2 + " --raw -o " + (dir / "s.off").string(),
        "hierarchy " + k1a1p + " --t0 0.2 --domain interior -o " + (dir / "h.h5").string()}) {
    const auto r = testing::run_cli_after("ulimit -f 16;", "-q " + command);
    EXPECT_EQ(r.signal, 0) << command << ": " << r.err;
    EXPECT_EQ(r.exit_code, 4) << command << ": " << r.err;
    EXPECT_EQ(entries(dir), 0u) << command;
  }
  fs::remove_all(dir);
}

TEST(OutputPaths, FullDiskIsExitCode4ForHierarchyAndSolve) {
  const auto dir = testing::test_dir("tmpfs");
  // A small tmpfs (needs root and a kernel that allows it; skipped otherwise).
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here";
  const auto r = testing::run_cli("-q hierarchy " + k1a1p + " --t0 0.2 --domain interior -o " +
                                  (dir / "h.h5").string());
  EXPECT_EQ(r.signal, 0) << r.err;
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(entries(dir), 0u);
  ::umount(dir.c_str());

  // solve: the hierarchy fits, its copy with the new fields does not.
  const auto home = testing::test_dir("solvehome");
  ASSERT_EQ(
      testing::run_cli("-q hierarchy " + k1a1p + " --t0 0.2,0.4 -o " + (home / "h.h5").string())
          .exit_code,
      0);
  const auto size = fs::file_size(home / "h.h5");
  const std::string options = "size=" + std::to_string(size + size / 2 + 65536);
  ASSERT_EQ(::mount("tmpfs", dir.c_str(), "tmpfs", 0, options.c_str()), 0);
  fs::copy_file(home / "h.h5", dir / "h.h5");
  const std::string before = testing::slurp(dir / "h.h5");
  const auto s = testing::run_cli("-q solve smoluchowski " + (dir / "h.h5").string());
  EXPECT_EQ(s.signal, 0) << s.err;
  EXPECT_EQ(s.exit_code, 4) << s.err;
  EXPECT_EQ(testing::slurp(dir / "h.h5"), before);
  EXPECT_EQ(entries(dir), 1u);
  ::umount(dir.c_str());
  fs::remove_all(dir);
  fs::remove_all(home);
}

TEST(OutputPaths, InterruptDeletesTheTemporaryBeingWritten) {
  // A child writes an output whose writer stalls half-way; SIGINT / SIGTERM arrive while the
  // temporary exists. The child must die by that signal and leave no file behind.
  for (int signal_number : {SIGINT, SIGTERM}) {
    const auto dir = testing::test_dir("signal" + std::to_string(signal_number));
    const pid_t child = ::fork();
    if (child == 0) {
      install_interrupt_cleanup();
      write_file_atomically(dir / "out.txt", [](std::ostream& o) {
        o << "half" << std::flush;
        ::pause();  // until the signal
      });
      ::_exit(0);
    }
    bool seen = false;
    for (int i = 0; i < 20000 && !seen; ++i) {
      for (const auto& entry : fs::directory_iterator(dir))
        seen = seen || entry.path().filename().string().find(".tmp") != std::string::npos;
      if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_TRUE(seen);
    ::kill(child, signal_number);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), signal_number);
    EXPECT_EQ(entries(dir), 0u);
    fs::remove_all(dir);
  }
}

TEST(OutputPaths, InterruptDuringHierarchyLeavesNothing) {
  // The real CLI on mAChE (long enough that it is still working after a second on an idle
  // machine; fas2 can finish first), interrupted while it works: it ends by the signal
  // (status 130 in a shell) and leaves no file.
  const auto dir = testing::test_dir("cli_signal");
  const std::string out = (dir / "h.h5").string();
  const std::string mache = std::string(MOLMESH_TEST_DATA_DIR) + "/mache.pqr";
  const pid_t child = ::fork();
  if (child == 0) {
    ::execl(MOLMESH_CLI_PATH, "molmesh", "-q", "hierarchy", mache.c_str(), "--t0", "0.1,0.3", "-o",
            out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::this_thread::sleep_for(std::chrono::seconds(1));
  ::kill(child, SIGINT);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_EQ(entries(dir), 0u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
