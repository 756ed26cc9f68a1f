#pragma once
// Debian's APBS (package apbs) in finite-element mode on a molmesh mesh, for the tests that
// check a mesh end to end against Born's analytic solvation energy: the input text, the run
// and the energy APBS prints.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "support/process.hpp"

namespace molmesh::testing {

// The Born ion as a PQR file: one ion of radius 3 Å and charge +1 at the origin.
inline constexpr const char* kBornIonPqr =
    "ATOM      1  I   ION     1       0.000   0.000   0.000  1.00  3.00\n";

// Whether `apbs` is on the PATH.
bool apbs_installed();

// One `elec` block: fe-manual on the given mesh (usemesh 1) with molecule 1, linearised PB,
// solute dielectric 1 and solvent dielectric `solvent_dielectric`. One solve (maxsolve 1) of
// APBS's refinement of the mesh: its accuracy is that of the mesh given.
std::string apbs_fe_elec_block(const std::string& name, double solvent_dielectric);

// A whole APBS input: reads `pqr` and the MCSF mesh `mesh` (paths as APBS sees them, i.e.
// relative to the folder it runs in) and prints the solvation energy, the solve at
// dielectric 78.54 minus the same solve at 1 (so the mesh's own error mostly cancels).
std::string apbs_solvation_input(const std::string& pqr, const std::string& mesh);

// Runs `apbs INPUT` in `directory` (INPUT relative to it).
CommandRun run_apbs_in(const std::filesystem::path& directory, const std::string& input);

// The value of APBS's "Global net ELEC energy = ... kJ/mol" line in `out`; nullopt when it
// has none.
std::optional<double> apbs_global_elec_energy(const std::string& out);

// The end of APBS's stdout (its last `chars` characters), for a failure message.
std::string apbs_output_tail(const CommandRun& run, std::size_t chars = 3000);

// Born's solvation energy (kJ/mol) of an ion of radius `radius` (Å) and charge `charge` (e)
// moving from vacuum into a solvent of `solvent_dielectric`:
// -(q^2 * 1389.35458 / (2a)) * (1 - 1/eps). The 3 Å monovalent ion in water: -228.61.
double born_solvation_energy_kj_mol(double radius, double charge = 1.0,
                                    double solvent_dielectric = 78.54);

}  // namespace molmesh::testing
