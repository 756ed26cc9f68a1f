#include "support/apbs.hpp"

#include <regex>
#include <sstream>

#include "support/files.hpp"

namespace molmesh::testing {

bool apbs_installed() { return run_command("command -v apbs").exit_code == 0; }

std::string apbs_fe_elec_block(const std::string& name, double solvent_dielectric) {
  std::ostringstream s;
  s << "elec name " << name << "\n"
    << "  fe-manual\n  domainLength 40 40 40\n  etol 0.1\n  ekey glob\n  akeyPRE geom\n"
    << "  akeySOLVE resi\n  targetNum 10\n  targetRes 0.0\n  maxsolve 1\n  maxvert 1000000\n"
    << "  usemesh 1\n  mol 1\n  lpbe\n  bcfl mdh\n  pdie 1.0\n  sdie " << solvent_dielectric << "\n"
    << "  srfm mol\n  srad 1.4\n  swin 0.3\n  sdens 10.0\n  temp 298.15\n"
    << "  calcenergy total\n  calcforce no\nend\n";
  return s.str();
}

std::string apbs_solvation_input(const std::string& pqr, const std::string& mesh) {
  return "read\n  mol pqr " + pqr + "\n  mesh mcsf " + mesh + "\nend\n" +
         apbs_fe_elec_block("solvated", 78.54) + apbs_fe_elec_block("reference", 1.0) +
         "print elecEnergy solvated - reference end\nquit\n";
}

CommandRun run_apbs_in(const std::filesystem::path& directory, const std::string& input) {
  return run_command("cd " + shell_quoted(directory.string()) + " && apbs " + shell_quoted(input));
}

std::optional<double> apbs_global_elec_energy(const std::string& out) {
  // e.g. "  Global net ELEC energy = -2.286071850994E+02 kJ/mol"
  static const std::regex energy(R"(Global net ELEC energy\s*=\s*([-+0-9.eE]+)\s*kJ/mol)");
  std::smatch match;
  if (!std::regex_search(out, match, energy)) return std::nullopt;
  return std::stod(match[1].str());
}

std::string apbs_output_tail(const CommandRun& run, std::size_t chars) {
  return run.out.substr(run.out.size() > chars ? run.out.size() - chars : 0);
}

double born_solvation_energy_kj_mol(double radius, double charge, double solvent_dielectric) {
  // 1389.35458 kJ/mol Å e^-2: e^2 / (4 pi eps0) in these units.
  return -(charge * charge * 1389.35458 / (2.0 * radius)) * (1.0 - 1.0 / solvent_dielectric);
}

}  // namespace molmesh::testing
