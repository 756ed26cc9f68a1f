// GAMer §4.2 on a real external mesh: the molecular surface Debian's EDTSurf makes for
// mAChE (~250k vertices, angles from 8° to 162°) goes through `molmesh improve` and must meet
// the paper's Fig. 10 numbers: closed and manifold, min angle >= 22°, max <= 130°, >= 88% of
// angles in [40°, 80°], at least 2x fewer vertices, mean dislocation <= 0.05 Å.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace molmesh {
namespace {

namespace fs = std::filesystem;

// EDTSurf reads PDB only and assigns its own radii by atom type; hydrogens are left out as
// in a crystal structure.
void write_heavy_atom_pdb(const Atoms& atoms, const fs::path& path) {
  std::ofstream out(path);
  int serial = 0;
  for (const Atom& a : atoms) {
    const std::string& n = a.atom_name;
    const auto first_letter = n.find_first_not_of("0123456789");
    if (first_letter == std::string::npos || n[first_letter] == 'H') continue;
    // pdb2pqr's terminal pseudo-residues are ordinary residues to EDTSurf.
    const std::string res =
        a.residue_name == "NTER" || a.residue_name == "CTER" ? "GLY" : a.residue_name;
    char line[100];
    std::snprintf(line, sizeof line,
                  "ATOM  %5d %-4s %3.3s A%4d    %8.3f%8.3f%8.3f  1.00  0.00          %2s\n",
                  ++serial % 100000, (n.size() < 4 ? " " + n : n).c_str(), res.c_str(),
                  a.residue_number % 10000, a.center.x(), a.center.y(), a.center.z(),
                  n.substr(first_letter, 1).c_str());
    out << line;
  }
  out << "END\n";
}

TEST(EdtsurfImprove, MacheMeetsThePaperFloors) {
  const fs::path dir = testing::test_dir();
  write_heavy_atom_pdb(read_atoms(MOLMESH_TEST_DATA_DIR "/mache.pqr"), dir / "mache.pdb");
  const testing::CommandRun edtsurf = testing::run_command(
      "cd " + testing::shell_quoted(dir.string()) + " && EDTSurf -i mache.pdb -o mache_edt -h 2");
  ASSERT_EQ(edtsurf.exit_code, 0)
      << "EDTSurf (Debian package edtsurf, tools/debian-packages.txt) failed:\n"
      << edtsurf.output();
  const fs::path ply = dir / "mache_edt.ply";
  ASSERT_TRUE(fs::exists(ply));

  const fs::path out = dir / "mache_improved.off";
  const fs::path stats = dir / "mache_improved.json";
  const testing::CliRun run = testing::run_cli("--quiet improve " + ply.string() + " -o " +
                                               out.string() + " --stats " + stats.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::ifstream in(stats);
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& input = j["input"]["input_surface"];
  // The input really is the poor external mesh the floor is about.
  EXPECT_GT(input["vertices"].get<std::size_t>(), 200000u);
  EXPECT_LT(input["min_angle_deg"].get<double>(), 15.0);
  EXPECT_GT(input["max_angle_deg"].get<double>(), 150.0);

  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_TRUE(j["manifold"].get<bool>());
  EXPECT_GE(j["min_angle_deg"].get<double>(), 22.0);
  EXPECT_LE(j["max_angle_deg"].get<double>(), 130.0);
  EXPECT_GE(j["fraction_angles_40_80"].get<double>(), 0.88);
  EXPECT_LE(2 * j["vertices"].get<std::size_t>(), input["vertices"].get<std::size_t>());
  EXPECT_LE(j["dislocation_mean"].get<double>(), 0.05);
  EXPECT_EQ(j["components"].get<int>(), input["components"].get<int>());
  RecordProperty("vertices", std::to_string(j["vertices"].get<std::size_t>()));
  RecordProperty("min_angle", std::to_string(j["min_angle_deg"].get<double>()));
  RecordProperty("max_angle", std::to_string(j["max_angle_deg"].get<double>()));
  RecordProperty("fraction_40_80", std::to_string(j["fraction_angles_40_80"].get<double>()));
  RecordProperty("mean_dislocation", std::to_string(j["dislocation_mean"].get<double>()));
}

}  // namespace
}  // namespace molmesh
