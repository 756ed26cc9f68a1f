#pragma once
// Physical constants at the solvers' user-facing edges (the library works in Å).
namespace molmesh::solvers::units {

inline constexpr double kCoulombKjAngstromPerMol = 1389.35458;  // kJ Å / (mol e^2)
inline constexpr double kAvogadro = 6.02214076e23;              // 1/mol
inline constexpr double kLitresPerCubicAngstrom = 1e-27;
inline constexpr double kSquareAngstromPerSquareCm = 1e16;

// k in Å^3/s (per molecule) -> M^-1 s^-1.
inline constexpr double rate_to_per_molar_per_second(double cubic_angstrom_per_s) {
  return cubic_angstrom_per_s * kLitresPerCubicAngstrom * kAvogadro;
}

}  // namespace molmesh::solvers::units
