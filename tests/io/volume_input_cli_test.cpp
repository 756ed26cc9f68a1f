// Scalar volumes as input (GAMer Fig. 1): a blurred molecule written by molmesh and read back
// must contour to the same surface as the atoms path, a hand-made MRC map of a known field
// must give the known shape, and the surface command must accept both and --blur fast.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "io/mrc_test_file.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/volume_io.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/processing/dislocation.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

int molmesh(const std::string& args, std::string* err = nullptr) {
  const testing::CliRun run = testing::run_cli("--quiet " + args);
  if (err) *err = run.err;
  return run.exit_code;
}

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

TEST(VolumeInput, WrittenBlurContoursLikeTheAtomsPath) {
  const Atoms atoms = read_atoms(MOLMESH_TEST_DATA_DIR "/1a1p.pqr");
  SurfacePipelineOptions options;
  options.surface = SurfaceKind::kGaussian;  // contoured at isovalue 1, as the volume is below
  options.raw = true;
  options.keep_volume = true;
  const SurfacePipelineResult direct = surface_from_atoms(atoms, options);
  ASSERT_EQ(direct.volume.dims, direct.grid_dims);
  for (const char* ext : {".dx", ".mrc"}) {
    const fs::path file = testing::test_dir() / (std::string("1a1p") + ext);
    write_volume(file, direct.volume);
    const Grid back = read_volume(file);
    EXPECT_EQ(back.dims, direct.volume.dims);
    const SurfacePipelineResult contoured = surface_from_grid(back, options);
    const SurfaceStats a = compute_surface_stats(direct.surface);
    const SurfaceStats b = compute_surface_stats(contoured.surface);
    EXPECT_EQ(b.vertices, a.vertices) << ext;
    EXPECT_TRUE(b.closed && b.manifold) << ext;
    // Only the file's number precision separates the two (float32 for MRC).
    const Dislocation d = measure_dislocation(contoured.surface, direct.surface);
    EXPECT_LT(d.max, 1e-4) << ext;
    EXPECT_NEAR(b.volume, a.volume, 1e-5 * a.volume) << ext;
  }
}

// A mode-2 MRC2014 map of f(x) = 2 - |x - c|^2 / R^2 written byte by byte: the level f = 1
// is the sphere of radius R about c.
void write_sphere_mrc(const fs::path& path, int n, double h, const Vec3& origin, const Vec3& c,
                      double radius) {
  std::vector<std::int32_t> header(256, 0);
  auto put_float = [&](int word, float v) { std::memcpy(&header[word - 1], &v, 4); };
  header[0] = header[1] = header[2] = n;  // NC NR NS
  header[3] = 2;                          // float32
  header[7] = header[8] = header[9] = n;  // MX MY MZ
  for (int w : {11, 12, 13}) put_float(w, static_cast<float>(n * h));
  for (int w : {14, 15, 16}) put_float(w, 90.0f);
  header[16] = 1;
  header[17] = 2;
  header[18] = 3;
  for (int k = 0; k < 3; ++k) put_float(50 + k, static_cast<float>(origin[k]));
  std::memcpy(&header[52], "MAP ", 4);
  const unsigned char stamp[4] = {0x44, 0x44, 0, 0};
  std::memcpy(&header[53], stamp, 4);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(header.data()), 1024);
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const Vec3 p = origin + h * Vec3(i, j, k);
        const float v = static_cast<float>(2.0 - (p - c).squaredNorm() / (radius * radius));
        out.write(reinterpret_cast<const char*>(&v), 4);
      }
    }
  }
}

TEST(VolumeInput, HandMadeMrcSphereThroughTheSurfaceCommand) {
  const fs::path map = testing::test_dir() / "sphere.mrc";
  const Vec3 origin(-10.0, 5.0, 2.0);
  const Vec3 centre = origin + Vec3::Constant(8.0);
  const double radius = 6.0;
  write_sphere_mrc(map, 33, 0.5, origin, centre, radius);
  const fs::path out = testing::test_dir() / "sphere.off";
  const fs::path raw = testing::test_dir() / "sphere_raw.off";
  const fs::path stats = testing::test_dir() / "sphere.json";
  std::string err;
  // Raw marching cubes: where the map says the sphere is (origin, spacing, axis order).
  ASSERT_EQ(molmesh("surface " + map.string() + " --isovalue 1 --raw -o " + raw.string(), &err), 0)
      << err;
  const SurfaceMesh mesh = read_surface_mesh(raw);
  double worst = 0.0;
  for (const Vec3& p : mesh.points) worst = std::max(worst, std::abs((p - centre).norm() - radius));
  EXPECT_LT(worst, 0.02);
  const double sphere = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  EXPECT_NEAR(compute_surface_stats(mesh).volume, sphere, 0.01 * sphere);
  // The full pipeline on a volume input: closed, one piece, and (coarsened and smoothed, on
  // a sphere of only 6 Å) within a few percent of the volume.
  ASSERT_EQ(molmesh("surface " + map.string() + " --isovalue 1 -o " + out.string() + " --stats " +
                        stats.string(),
                    &err),
            0)
      << err;
  const nlohmann::json j = read_json(stats);
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_TRUE(j["manifold"].get<bool>());
  EXPECT_EQ(j["components"].get<int>(), 1);
  EXPECT_NEAR(j["volume"].get<double>(), sphere, 0.05 * sphere);
  EXPECT_LT(j["vertices"].get<int>(), static_cast<int>(mesh.points.size()));
}

TEST(VolumeInput, SurfaceCommandWritesAndRecontoursItsVolumeAndBlursFast) {
  const std::string pqr = MOLMESH_TEST_DATA_DIR "/1a1p.pqr";
  const fs::path vol = testing::test_dir() / "cli_1a1p.mrc";
  const fs::path a = testing::test_dir() / "cli_atoms.off";
  const fs::path b = testing::test_dir() / "cli_volume.off";
  const fs::path c = testing::test_dir() / "cli_fast.off";
  const fs::path cs = testing::test_dir() / "cli_fast.json";
  std::string err;
  ASSERT_EQ(molmesh("surface " + pqr + " --surface gaussian --raw -o " + a.string() +
                        " --write-volume " + vol.string(),
                    &err),
            0)
      << err;
  ASSERT_EQ(molmesh("surface " + vol.string() + " --raw --isovalue 1 -o " + b.string(), &err), 0)
      << err;
  const SurfaceMesh sa = read_surface_mesh(a);
  const SurfaceMesh sb = read_surface_mesh(b);
  EXPECT_EQ(sa.points.size(), sb.points.size());
  EXPECT_LT(measure_dislocation(sb, sa).max, 1e-4);

  ASSERT_EQ(molmesh("surface " + pqr + " --surface gaussian --raw --blur fast -o " + c.string() +
                        " --stats " + cs.string(),
                    &err),
            0)
      << err;
  const nlohmann::json j = read_json(cs);
  EXPECT_EQ(j["parameters"]["blur"].get<std::string>(), "fast");
  EXPECT_TRUE(j["closed"].get<bool>());
  // Eq. 2 with one decay rate is a different (slightly smoother) model than Eq. 1, but the
  // same molecule: docs/inputs.md has the measured dislocations.
  const Dislocation d = measure_dislocation(read_surface_mesh(c), sa);
  EXPECT_LT(d.mean, 0.5);
  EXPECT_EQ(molmesh("surface " + pqr + " --blur slow -o " + c.string()), 2);
}

// Issue 18: a volume whose data does not match its header is exit code 3 with the file (and
// for DX the line) named, and no output; the DX values on later lines and the MRC bytes
// after the data were exit 0 before. tests/io/volume_io_test.cpp has each reader message.
TEST(VolumeInput, DataThatDoesNotMatchTheHeaderExitsWithCode3) {
  const std::string dx_head =
      "object 1 class gridpositions counts 2 1 1\norigin 0 0 0\ndelta 1 0 0\ndelta 0 1 0\n"
      "delta 0 0 1\nobject 3 class array type double rank 0 items 2 data follows\n";
  const std::string dx_tail = "attribute \"dep\" string \"positions\"\n";
  test::MrcSpec spec;
  spec.n = {2, 2, 2};
  const std::string mrc = test::make_mrc(spec, std::vector<double>(8, 1.0));
  std::string nsymbt_past_end = mrc;
  const std::int32_t nsymbt = 4096;
  std::memcpy(nsymbt_past_end.data() + 4 * 23, &nsymbt, 4);
  struct Case {
    const char* file;
    std::string bytes;
    std::string where;  // after the path in the message
  };
  const Case cases[] = {
      {"fewer_eof.dx", dx_head + "1\n", ":7: file ends after 1 of 2 values"},
      {"fewer.dx", dx_head + "1\n" + dx_tail, ":8: data ends after 1 of 2 values"},
      {"more_same_line.dx", dx_head + "1 2 3\n" + dx_tail, ":7: more values than the 2 items"},
      {"more_next_line.dx", dx_head + "1 2\n3\n" + dx_tail, ":8: more values than the 2 items"},
      {"short.mrc", mrc.substr(0, mrc.size() - 4), ": file has 1052 bytes"},
      {"trailing.mrc", mrc + std::string(4, '\0'), ": file has 1060 bytes"},
      {"nsymbt.map", nsymbt_past_end, ": file has 1056 bytes"},
  };
  const fs::path out = testing::test_dir() / "out.off";
  for (const Case& c : cases) {
    const fs::path file = testing::write_file(testing::test_dir() / c.file, c.bytes);
    std::string err;
    EXPECT_EQ(molmesh("surface " + file.string() + " --isovalue 0.5 -o " + out.string(), &err), 3)
        << c.file << ": " << err;
    EXPECT_NE(err.find("molmesh: error: " + file.string() + c.where), std::string::npos)
        << c.file << ": " << err;
    EXPECT_FALSE(fs::exists(out)) << c.file;
  }
}

}  // namespace
}  // namespace molmesh
