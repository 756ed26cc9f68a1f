#pragma once
// PQR as APBS and pdb2pqr write it: ATOM/HETATM records whose fields are separated by
// blanks rather than fixed columns (serial, atom name, residue name, optional chain,
// residue number, x, y, z, charge, radius, optional trailing columns such as the element).
// Fields that fixed-column writers glue together are split again: chain+residue number
// ("A1000"), negative coordinates ("-12.345-6.789"), "HETATM12345". Other records (REMARK,
// TER, END, CRYST1, ...) are ignored; only the first MODEL is read.
#include <string>
#include <string_view>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"

namespace molmesh {

// `name` names the file in errors ("name:line: what"). Does not filter or check for an
// empty result (read_atoms does).
Atoms parse_pqr(std::string_view text, const std::string& name, const Reporter& reporter = {});

}  // namespace molmesh
