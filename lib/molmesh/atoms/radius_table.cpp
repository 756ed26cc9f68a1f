#include "molmesh/atoms/radius_table.hpp"

#include <algorithm>
#include <cctype>

namespace molmesh {

std::string to_upper(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}

std::optional<double> RadiusTable::lookup(const Atom& atom) const {
  const std::string residue = to_upper(atom.residue_name);
  const std::string name = to_upper(atom.atom_name);
  for (const auto& key : {std::pair{residue, name}, std::pair<std::string, std::string>{"*", name},
                          std::pair<std::string, std::string>{residue, "*"}}) {
    if (auto it = by_residue_atom.find(key); it != by_residue_atom.end()) return it->second;
  }
  if (!atom.element.empty()) {
    if (auto it = by_element.find(to_upper(atom.element)); it != by_element.end())
      return it->second;
  }
  if (auto it = by_element.find("*"); it != by_element.end()) return it->second;
  return std::nullopt;
}

const RadiusTable& builtin_radius_table() {
  static const RadiusTable table = [] {
    RadiusTable t;
    t.source = "built-in Bondi (1964) table";
    // Bondi, J. Phys. Chem. 68, 441 (1964), Table I, with H = 1.20 A as Bondi recommends.
    t.by_element = {{"H", 1.20},
                    {"D", 1.20},
                    {"HE", 1.40},
                    {"C", 1.70},
                    {"N", 1.55},
                    {"O", 1.52},
                    {"F", 1.47},
                    {"NE", 1.54},
                    {"SI", 2.10},
                    {"P", 1.80},
                    {"S", 1.80},
                    {"CL", 1.75},
                    {"AR", 1.88},
                    {"AS", 1.85},
                    {"SE", 1.90},
                    {"BR", 1.85},
                    {"KR", 2.02},
                    {"TE", 2.06},
                    {"I", 1.98},
                    {"XE", 2.16},
                    {"LI", 1.82},
                    {"NA", 2.27},
                    {"MG", 1.73},
                    {"K", 2.75},
                    {"NI", 1.63},
                    {"CU", 1.40},
                    {"ZN", 1.39},
                    {"GA", 1.87},
                    {"PD", 1.63},
                    {"AG", 1.72},
                    {"CD", 1.58},
                    {"IN", 1.93},
                    {"SN", 2.17},
                    {"PT", 1.72},
                    {"AU", 1.66},
                    {"HG", 1.55},
                    {"TL", 1.96},
                    {"PB", 2.02},
                    {"U", 1.86},
                    // Mantina, Chamberlin, Valero, Cramer, Truhlar, J. Phys. Chem. A 113, 5806
                    // (2009), Table 12: main-group elements missing from Bondi, on the same scale.
                    {"BE", 1.53},
                    {"B", 1.92},
                    {"AL", 1.84},
                    {"CA", 2.31},
                    {"GE", 2.11},
                    {"RB", 3.03},
                    {"SR", 2.49},
                    {"SB", 2.06},
                    {"CS", 3.43},
                    {"BA", 2.68},
                    {"BI", 2.07},
                    {"PO", 1.97},
                    {"AT", 2.02},
                    {"RN", 2.20},
                    {"FR", 3.48},
                    {"RA", 2.83}};
    return t;
  }();
  return table;
}

}  // namespace molmesh
