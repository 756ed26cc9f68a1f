// Damaged hierarchy files (issue 18, finding 4): damaged contents are refused on read with
// an InputError naming the dataset, bytes libhdf5 cannot parse are exit code 3 from `info`
// and `solve` (never a signal, never a fault handler of the parent's run in the reading
// child), and `solve` on a refused file writes nothing.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hierarchy/hierarchy_support.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

Hierarchy small_hierarchy() {
  Hierarchy h = testing::cube_hierarchy(4, 2);
  h.parameters = {{"domain", "exterior"}};
  h.input_name = "cube.pqr";
  return h;
}

// Applies a python h5py edit to a fresh copy of the small hierarchy; returns its path.
fs::path damaged(const fs::path& dir, const std::string& name, const std::string& edit) {
  const fs::path file = dir / (name + ".h5");
  write_hierarchy(file, small_hierarchy());
  testing::edit_with_h5py(file, edit);
  return file;
}

std::string read_error(const fs::path& file) {
  try {
    read_hierarchy(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(HierarchyDamage, DamagedContentsAreRefusedOnRead) {
  const auto dir = testing::test_dir("contents");
  ASSERT_EQ(read_error(damaged(dir, "intact", "pass")), "");
  const std::pair<const char*, const char*> cases[] = {
      {"levels/0/volume/cell_markers", "f['levels/0/volume/cell_markers'][0] = 2147483647"},
      {"prolongation", "f['transfer/1_to_0/volume/data'][0] = np.nan"},
      {"prolongation", "f['transfer/1_to_0/surface/data'][1] = np.inf"},
      {"vertex_markers",
       "n = len(f['levels/0/volume/points']); del f['levels/0/volume/vertex_markers']; "
       "f['levels/0/volume/vertex_markers'] = np.zeros(n + 5, dtype='i4')"},
      {"cell_markers",
       "del f['levels/1/volume/cell_markers']; "
       "f['levels/1/volume/cell_markers'] = np.zeros(0, dtype='i4')"},
      {"permutation",
       "n = len(f['levels/0/volume/points']); f['levels/0/volume/permutation'][3] = n"},
      {"permutation", "f['levels/0/volume/permutation'][3] = f['levels/0/volume/permutation'][4]"},
      {"points", "f['levels/1/volume/points'][2, 1] = np.nan"},
      {"t0", "f['levels/1'].attrs['t0'] = np.nan"},
      {"provenance", "f['levels/1/surface/provenance'][0] = 100000"},
  };
  for (const auto& [expected, edit] : cases) {
    const std::string message = read_error(damaged(dir, "case", edit));
    EXPECT_NE(message.find(expected), std::string::npos) << edit << " -> '" << message << "'";
  }
  fs::remove_all(dir);
}

TEST(HierarchyDamage, SolveOnANanTransferFailsBeforeWritingAnything) {
  const auto dir = testing::test_dir("solve");
  const fs::path file = damaged(dir, "nan", "f['transfer/1_to_0/volume/data'][0] = np.nan");
  const std::string before = testing::slurp(file);
  const auto r = testing::run_cli("-q solve smoluchowski " + file.string() + " --json " +
                                  (dir / "r.json").string());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("not finite"), std::string::npos) << r.err;
  EXPECT_EQ(testing::slurp(file), before);
  EXPECT_FALSE(fs::exists(dir / "r.json"));
  fs::remove_all(dir);
}

// Where the fault handler of the test below leaves its mark (a path fixed before it is
// installed: a handler may only call async-signal-safe functions).
char fault_mark[4096];

extern "C" void leave_fault_mark(int) {
  const int fd = ::open(fault_mark, O_CREAT | O_WRONLY, 0644);
  if (fd >= 0) ::close(fd);
  ::_exit(99);
}

TEST(HierarchyDamage, TheReaderChildDiesOfTheFaultWithoutTheParentsHandlers) {
  // A file on which libhdf5 1.10.8 segfaults (SIGSEGV in H5A__close, found by fuzzing; the
  // other two inputs kept with it crash it in the CLI's process but not in this one: where
  // the damaged read lands depends on the heap). The
  // fault is contained in the probe's child process, which must die of it without running
  // the handlers it inherits: a fuzzer's (which saved the input as a crash of the parent),
  // a sanitizer's (which reported it), Python's faulthandler.
  const fs::path input = fs::path(MOLMESH_TEST_DATA_DIR).parent_path() /
                         "fuzz/crashes/hierarchy/hdf5-segv-in-child-3.h5";
  const fs::path dir = testing::test_dir();
  const fs::path file = testing::write_file(dir / "segv.h5", testing::slurp(input));
  const std::string mark = (dir / "handler-ran").string();
  ASSERT_LT(mark.size(), sizeof fault_mark);
  mark.copy(fault_mark, mark.size());
  fault_mark[mark.size()] = '\0';
  struct sigaction handler {
  }, previous{};
  handler.sa_handler = leave_fault_mark;
  sigemptyset(&handler.sa_mask);
  ASSERT_EQ(::sigaction(SIGSEGV, &handler, &previous), 0);
  std::string message;
  try {
    read_hierarchy(file);
  } catch (const InputError& e) {
    message = e.what();
  }
  ::sigaction(SIGSEGV, &previous, nullptr);
  EXPECT_NE(message.find("libhdf5 crashed reading it (signal 11)"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(mark)) << "the child ran the parent's fault handler";
}

TEST(HierarchyDamage, CorruptBytesAreExitCode3NeverASignal) {
  // The corruption: the 4 bytes 07 00 00 00 written into the file. In a 1a1p
  // hierarchy libhdf5 1.10.8 crashed (SIGSEGV in H5Aiterate2) at 12 offsets between 1200
  // and 1330 (the root object header's attributes) and looped forever at 3040 (refused
  // after the reader's 60 s limit: too slow for this test). Every 16th offset of bytes
  // 1000-1400 is tried here with both commands that read hierarchies, and the issue's own
  // offset, 1232.
  const auto dir = testing::test_dir("bytes");
  const fs::path intact = dir / "intact.h5";
  write_hierarchy(intact, small_hierarchy());
  const std::string original = testing::slurp(intact);
  const std::size_t end = std::min<std::size_t>(original.size() - 4, 1400);
  std::vector<std::size_t> offsets{1232};
  for (std::size_t offset = 1000; offset < end; offset += 16) offsets.push_back(offset);
  int refused = 0, accepted = 0;
  for (const std::size_t offset : offsets) {
    std::string bytes = original;
    bytes.replace(offset, 4, std::string("\x07\x00\x00\x00", 4));
    if (bytes == original) continue;
    const fs::path file = dir / "damaged.h5";
    testing::write_file(file, bytes);
    for (const char* command : {"info ", "solve smoluchowski --no-fields "}) {
      const auto r = testing::run_cli(std::string("-q ") + command + file.string());
      ASSERT_EQ(r.signal, 0) << command << "offset " << offset << ": " << r.err;
      // 0: the damage hit bytes nobody reads (or still valid values); 1: the solver refused
      // the (valid but different) data; otherwise only the input-error code.
      ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1 || r.exit_code == 3)
          << command << "offset " << offset << ": exit " << r.exit_code << " " << r.err;
      (r.exit_code == 3 ? refused : accepted) += 1;
    }
  }
  EXPECT_GT(refused, 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace molmesh
