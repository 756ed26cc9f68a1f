#pragma once
// PDB ATOM/HETATM records before gemmi sees them: the coordinate columns are checked
// strictly (gemmi reads "-7.1x8" as -7.1 without a word), and records whose coordinates are
// not in the fixed columns 31-54 (tab-separated or shifted fields, as in some APBS
// examples) are rewritten into fixed columns from their whitespace-separated fields. Lines
// gemmi 0.5 would misread are made safe for it too (pdb_records.cpp, scan_pdb_records).
#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>

namespace molmesh::io_detail {

struct PdbScan {
  std::unordered_map<int, std::size_t> lines;  // serial -> line; the first record wins
  std::optional<std::string> rewritten;        // the text for gemmi, if any line changed
  std::size_t whitespace_records = 0;          // records read from whitespace fields
  std::size_t first_whitespace_line = 0;
};

// Throws InputError at the record's line when its coordinates can be read neither from the
// fixed columns nor as whitespace-separated fields, or are not finite numbers.
PdbScan scan_pdb_records(const std::string& contents, const std::string& name);

}  // namespace molmesh::io_detail
