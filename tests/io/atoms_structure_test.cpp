#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "io/io_test_support.hpp"
#include "molmesh/atoms/radius_table.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/radius_table.hpp"
#include "molmesh/io/read_atoms.hpp"

namespace molmesh {
namespace {

using test::expect_input_error;
using test::write_text;

const std::filesystem::path kData = MOLMESH_TEST_DATA_DIR;

TEST(Structure, PdbAtomsGetBondiRadii) {
  const Atoms atoms = read_atoms(kData / "1a1p.pdb");
  ASSERT_EQ(atoms.size(), 208u);  // 205 ATOM + the 3-atom NH2 cap (HETATM)
  std::map<std::string, double> radius_of;
  for (const Atom& a : atoms) {
    ASSERT_FALSE(a.element.empty());
    radius_of[a.element] = a.radius;
  }
  EXPECT_DOUBLE_EQ(radius_of["C"], 1.70);
  EXPECT_DOUBLE_EQ(radius_of["N"], 1.55);
  EXPECT_DOUBLE_EQ(radius_of["O"], 1.52);
  EXPECT_DOUBLE_EQ(radius_of["S"], 1.80);
  EXPECT_DOUBLE_EQ(radius_of["H"], 1.20);
  // Same first atom as the PQR made from this PDB.
  EXPECT_EQ(atoms[0].atom_name, "N");
  EXPECT_EQ(atoms[0].residue_name, "ILE");
  EXPECT_DOUBLE_EQ(atoms[0].center.x(), -7.158);
  EXPECT_TRUE(atoms.back().hetatm);
  EXPECT_EQ(atoms.back().residue_name, "NH2");
}

TEST(Structure, PdbMatchesItsPqrCoordinates) {
  AtomReadOptions protein;
  protein.include_hetatm = false;
  const Atoms pdb = read_atoms(kData / "1a1p.pdb", protein);
  const Atoms pqr = read_atoms(kData / "1a1p.pqr");
  ASSERT_EQ(pdb.size(), 205u);
  // pdb2pqr rebuilds hydrogens and may flip histidine rings, but keeps every other heavy
  // atom where it was: each must have a PQR atom of the same residue at the same place.
  std::size_t heavy = 0, matched = 0;
  for (const Atom& a : pdb) {
    if (a.element == "H") continue;
    ++heavy;
    bool found = false;
    for (const Atom& b : pqr)
      if (b.residue_number == a.residue_number && (b.center - a.center).norm() < 1e-9) found = true;
    if (found)
      ++matched;
    else
      EXPECT_EQ(a.residue_name, "HIS") << a.atom_name << " " << a.residue_number;
  }
  EXPECT_GT(heavy, 90u);
  EXPECT_GE(matched + 4, heavy);  // at most one flipped ring
}

TEST(Structure, ApbsExamplePdbFilesReadOrFailWithALine) {
  // apbs-data's PDB files include hand-made ones: tab-separated, shifted columns, ligand
  // atoms without an element. Each either reads completely or fails naming its line.
  const std::filesystem::path root = "/usr/share/apbs/examples";
  ASSERT_TRUE(std::filesystem::is_directory(root))
      << "install apbs-data (tools/debian-packages.txt)";
  std::size_t ok = 0, failed = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".pdb") continue;
    std::size_t records = 0;
    bool has_altloc = false;
    {
      std::ifstream in(entry.path());
      std::string line;
      while (std::getline(in, line)) {
        if (line.rfind("ATOM", 0) != 0 && line.rfind("HETATM", 0) != 0) continue;
        ++records;
        // (Tab-separated records have no column 17.)
        if (line.size() > 16 && line[16] != ' ' && line.find('\t') == std::string::npos)
          has_altloc = true;
      }
    }
    int warnings = 0;
    Reporter reporter;
    // Records outside the fixed columns are read with their own warning (reader_robustness).
    reporter.on_warning = [&](std::string_view m) {
      if (m.find("whitespace-separated fields") == std::string_view::npos) ++warnings;
    };
    try {
      const Atoms atoms = read_atoms(entry.path(), {}, reporter);
      ++ok;
      if (!has_altloc) {
        EXPECT_EQ(atoms.size(), records) << entry.path();
        EXPECT_EQ(warnings, 0) << entry.path();
      } else {
        EXPECT_LT(atoms.size(), records) << entry.path();
        EXPECT_EQ(warnings, 1) << entry.path();
      }
      for (const Atom& a : atoms) ASSERT_GT(a.radius, 1.0) << entry.path();
    } catch (const InputError& e) {
      ++failed;
      EXPECT_GT(e.line(), 0u) << e.what();
    }
  }
  EXPECT_GE(ok, 15u);
  EXPECT_LE(failed, 4u);
}

TEST(Structure, AlternativeLocationsKeepTheFirstAndSameNamedAtomsStay) {
  const auto path = write_text(
      "alt.pdb",
      "ATOM      1  CA AALA A   1       1.000   0.000   0.000  0.60  0.00           C  \n"
      "ATOM      2  CA BALA A   1       1.500   0.000   0.000  0.40  0.00           C  \n"
      "ATOM      3  C   ALA A   1       2.000   0.000   0.000  1.00  0.00           C  \n"
      "HETATM    4  C   ALK B   2       5.000   0.000   0.000  1.00  0.00           C  \n"
      "HETATM    5  C   ALK B   2       6.000   0.000   0.000  1.00  0.00           C  \n");
  std::string warning;
  Reporter reporter;
  reporter.on_warning = [&](std::string_view m) { warning = m; };
  const Atoms atoms = read_atoms(path, {}, reporter);
  ASSERT_EQ(atoms.size(), 4u);  // CA B dropped; both alkane carbons named C kept
  EXPECT_DOUBLE_EQ(atoms[0].center.x(), 1.0);
  EXPECT_DOUBLE_EQ(atoms[3].center.x(), 6.0);
  EXPECT_NE(warning.find("1 of 2 alternative-location atoms dropped"), std::string::npos)
      << warning;
}

// gemmi reads a line only to column 120, but a byte >= 0x80 beyond that made it start a
// record there (a second atom from the tail of the first line); and it read a short LINK
// record's distance (columns 74-78) past the end of the line (ASan: the sanitizer leg).
// Both from fuzzing (tests/fuzz/crashes/pdb).
TEST(Structure, TextBeyondColumn120IsNotARecordAndShortLinkRecordsAreSafe) {
  const std::string atom1 =
      "ATOM      1  N   ALA A   1       1.000   0.000   0.000  1.00  0.00           N  ";
  const std::string atom2 =
      "ATOM      2  CA  ALA A   1       2.000   0.000   0.000  1.00  0.00           C  ";
  const std::string tail =
      "ATOM      3  C   ALA A   1       9.000   0.000   0.000  1.00  0.00           C  ";
  const std::string link =
      "LINK         N   ALA A   1                 CA  ALA A   1     1555   1555  1";
  ASSERT_EQ(link.size(), 75u);  // > 73 and < 78: the distance field is cut
  const auto path =
      write_text("long_line.pdb", atom1 + std::string(40, ' ') + "\xff" + tail + "\n" + link +
                                      "\n" + "SSBO" + link.substr(4) + "\n" + atom2 + "\nEND\n");
  const Atoms atoms = read_atoms(path);
  ASSERT_EQ(atoms.size(), 2u);
  EXPECT_DOUBLE_EQ(atoms[0].center.x(), 1.0);
  EXPECT_DOUBLE_EQ(atoms[1].center.x(), 2.0);
}

// gemmi reads a DBREF2 record's database positions (columns 46-55, 58-67) as ints without
// an overflow check: "3333333333" there was a signed overflow (UBSan, the sanitizer leg;
// tests/fuzz/crashes/pdb/gemmi_dbref2_int_overflow.pdb). molmesh reads nothing of DBREF, so
// such a value is blanked and the atoms read as ever.
TEST(Structure, DbrefPositionsBeyondAnIntAreSafe) {
  const std::string atom =
      "ATOM      1  N   ALA A   1       1.000   0.000   0.000  1.00  0.00           N  ";
  const std::string dbref1 = "DBREF1 1ABC A    1    10  UNP                  ABC_HUMAN";
  std::string dbref2 = "DBREF2 1ABC A     P12345";
  dbref2.resize(45, ' ');
  dbref2 += "3333333333";  // columns 46-55
  dbref2.resize(57, ' ');
  dbref2 += "9999999999";  // columns 58-67
  ASSERT_EQ(dbref2.substr(45, 10), "3333333333");
  // Also beyond column 120 (where the line is cut first), and short after a long line.
  const std::string longer = dbref2 + std::string(70, '5');
  const auto path = write_text("dbref2.pdb", dbref1 + "\n" + dbref2 + "\n" + longer + "\n" + atom +
                                                 "\n" + "DBREF2 1ABC A\nEND\n");
  const Atoms atoms = read_atoms(path);
  ASSERT_EQ(atoms.size(), 1u);
  EXPECT_DOUBLE_EQ(atoms[0].center.x(), 1.0);
}

// gemmi reads any record whose first four letters are HETA as HETATM; such a record with a
// coordinate that is no finite number must be refused like a HETATM one, not read as an
// atom at infinity (pdb fuzz campaign: tests/fuzz/crashes/pdb/gemmi_heta_record.pdb).
TEST(Structure, RecordsGemmiReadsAsAtomsAreCheckedLikeAtoms) {
  const std::string atom =
      "ATOM      1  N   ALA A   1       1.000   0.000   0.000  1.00  0.00           N  ";
  std::string heta =
      "HETAXX    2 FE   HEM A   2       2.000   0.000   0.000  1.00  0.00          FE  ";
  heta.replace(30, 8, " 1.0E999");
  expect_input_error([&] { read_atoms(write_text("heta.pdb", atom + "\n" + heta + "\n")); },
                     {"heta.pdb:2"});
}

TEST(Structure, FiltersHydrogens) {
  AtomReadOptions heavy;
  heavy.include_hydrogens = false;
  const Atoms atoms = read_atoms(kData / "1a1p.pdb", heavy);
  for (const Atom& a : atoms) EXPECT_NE(a.element, "H");
  EXPECT_GT(atoms.size(), 90u);
  EXPECT_LT(atoms.size(), 120u);
}

TEST(Structure, MmcifAndGzipGiveTheSameAtoms) {
  const Atoms pdb = read_atoms(kData / "1a1p.pdb");
  const Atoms cif = read_atoms(kData / "1a1p.cif");
  ASSERT_EQ(cif.size(), pdb.size());
  for (std::size_t i = 0; i < pdb.size(); ++i) {
    EXPECT_EQ(cif[i].atom_name, pdb[i].atom_name);
    EXPECT_EQ(cif[i].element, pdb[i].element);
    EXPECT_DOUBLE_EQ(cif[i].radius, pdb[i].radius);
    EXPECT_LT((cif[i].center - pdb[i].center).norm(), 1e-9);
  }
  const std::string text = testing::slurp(kData / "1a1p.pdb");
  const auto gz = testing::test_dir() / "1a1p.pdb.gz";
  gzFile out = gzopen(gz.string().c_str(), "wb");
  ASSERT_NE(out, nullptr);
  ASSERT_EQ(gzwrite(out, text.data(), static_cast<unsigned>(text.size())),
            static_cast<int>(text.size()));
  gzclose(out);
  const Atoms zipped = read_atoms(gz);
  ASSERT_EQ(zipped.size(), pdb.size());
  EXPECT_LT((zipped[100].center - pdb[100].center).norm(), 1e-12);
}

TEST(Structure, MmcifCoordinateThatIsNotANumberNamesItsLine) {
  // gemmi reads "4.681.0" (or "?") as NaN and keeps the atom (fuzz inputs
  // tests/fuzz/crashes/mmcif/mmcif-malformed-coordinate-*); parse_structure returned it and
  // read_atoms refused it later with neither line nor value. The quoted name with a blank and
  // the text field before the bad row check that the line is counted as gemmi tokenizes.
  const std::string head =
      "data_t\n# a comment\nloop_\n_atom_site.group_PDB\n_atom_site.id\n"
      "_atom_site.type_symbol\n_atom_site.label_atom_id\n_atom_site.label_alt_id\n"
      "_atom_site.label_comp_id\n_atom_site.label_asym_id\n_atom_site.Cartn_x\n"
      "_atom_site.Cartn_y\n_atom_site.Cartn_z\n_atom_site.occupancy\n"
      "_atom_site.B_iso_or_equiv\n_atom_site.auth_seq_id\n"
      "ATOM 1 N N . ALA A 0.0 0.0 0.0 1 0 1\n"
      "ATOM 2 C \"C A\" . ALA A 1.5 0.0 0.0 1 0 1\n"
      "ATOM 3 C\n;CB\n;\n. ALA A 2.0 1.4 0.0 1 0 1\n";
  EXPECT_EQ(
      read_atoms(write_text("good.cif", head + "ATOM 4 O O . ALA A 1.2 4.6 0 1 0 1\n")).size(), 4u);
  expect_input_error(
      [&] { read_atoms(write_text("bad.cif", head + "ATOM 4 O O . ALA A 1.2 4.681.0 0 1 0 1\n")); },
      {"bad.cif:23:", "_atom_site.Cartn_y '4.681.0' of atom 4 is not a finite number"});
  // A loop that does not start its line: counted from the line start, the token found is not
  // the value, and the message has no line rather than one found by a miscount.
  std::string shifted = head + "ATOM 4 O O . ALA A 1.2 4.681.0 0 1 0 1\n";
  shifted.replace(shifted.find("\nloop_"), 6, "\n_cell.length_a 1 loop_");
  expect_input_error([&] { read_atoms(write_text("shift.cif", shifted)); },
                     {"shift.cif: _atom_site.Cartn_y '4.681.0' of atom 4"});
  // One atom as tag-value pairs: the line of the tag.
  expect_input_error(
      [] {
        read_atoms(write_text("pair.cif",
                              "data_t\n_atom_site.id 1\n_atom_site.type_symbol N\n"
                              "_atom_site.label_atom_id N\n_atom_site.label_alt_id .\n"
                              "_atom_site.label_comp_id ALA\n_atom_site.label_asym_id A\n"
                              "_atom_site.Cartn_x 0\n_atom_site.Cartn_y 0\n_atom_site.Cartn_z ?\n"
                              "_atom_site.occupancy 1\n_atom_site.B_iso_or_equiv 0\n"
                              "_atom_site.auth_seq_id 1\n"));
      },
      {"pair.cif:10:", "Cartn_z '?'"});
}

// The first atoms of 1a1p (tests/fuzz/corpus/mmcif/1a1p_head.cif): atom N is on line 20 + N.
std::string mmcif_head() {
  std::string text =
      "data_1a1p\nloop_\n_atom_site.id\n_atom_site.type_symbol\n_atom_site.label_atom_id\n"
      "_atom_site.label_alt_id\n_atom_site.label_comp_id\n_atom_site.label_asym_id\n"
      "_atom_site.label_entity_id\n_atom_site.label_seq_id\n_atom_site.pdbx_PDB_ins_code\n"
      "_atom_site.Cartn_x\n_atom_site.Cartn_y\n_atom_site.Cartn_z\n_atom_site.occupancy\n"
      "_atom_site.B_iso_or_equiv\n_atom_site.pdbx_formal_charge\n_atom_site.auth_seq_id\n"
      "_atom_site.auth_asym_id\n_atom_site.pdbx_PDB_model_num\n";
  const char* atoms[] = {"1 N N", "2 C CA", "3 C C", "4 O O", "5 C CB"};
  for (int i = 0; i < 5; ++i)
    text += std::string(atoms[i]) + " . ILE poly . 1 ? -7.1 5." + std::to_string(i) +
            " 0.6 1 0 ? 1 '' 1\n";
  return text;
}

// Replaces the `field`-th field (from 0) of atom `atom`'s line by `value`.
std::string with_atom_field(std::string text, int atom, int field, const std::string& value) {
  std::size_t pos = 0;
  for (int line = 1; line < 20 + atom; ++line) pos = text.find('\n', pos) + 1;
  for (int f = 0; f < field; ++f) pos = text.find(' ', pos) + 1;
  const std::size_t end = text.find_first_of(" \n", pos);
  return text.replace(pos, end - pos, value);
}

TEST(Structure, MmcifIntegerBeyondIntNamesItsLineAndColumn) {
  // gemmi parses integer columns without an overflow check (signed overflow: a 40-digit
  // _atom_site.id was UBSan's report, tests/fuzz/crashes/mmcif/mmcif-atom-id-overflow-1), and a
  // residue number of 99999999999999 became a wrapped one, exit 0. Every column it reads as an
  // int is checked first (atoms_structure.cpp, kIntColumns), naming file:line and column.
  const std::string head = mmcif_head();
  EXPECT_EQ(read_atoms(write_text("good.cif", head)).size(), 5u);
  // An insertion code after the residue number is part of auth_seq_id; a negative number,
  // '?' and '.' are values gemmi reads.
  EXPECT_EQ(read_atoms(write_text("icode.cif", with_atom_field(head, 5, 15, "12A"))).size(), 5u);
  EXPECT_EQ(read_atoms(write_text("neg.cif", with_atom_field(head, 5, 7, "-3"))).size(), 5u);
  EXPECT_EQ(read_atoms(write_text("null.cif", with_atom_field(head, 5, 7, "."))).size(), 5u);
  const std::string range = "is not an integer from -2147483648 to 2147483647";
  expect_input_error(
      [&] { read_atoms(write_text("a.cif", with_atom_field(head, 4, 15, "99999999999999"))); },
      {"a.cif:24: _atom_site.auth_seq_id '99999999999999' of atom 4 " + range});
  expect_input_error(
      [&] { read_atoms(write_text("b.cif", with_atom_field(head, 5, 7, "-99999999999999"))); },
      {"b.cif:25: _atom_site.label_seq_id '-99999999999999' of atom 5 " + range});
  expect_input_error(
      [&] { read_atoms(write_text("c.cif", with_atom_field(head, 3, 15, "99999999999A"))); },
      {"c.cif:23: _atom_site.auth_seq_id '99999999999A' of atom 3 " + range});
  expect_input_error(
      [&] { read_atoms(write_text("d.cif", with_atom_field(head, 2, 0, std::string(40, '9')))); },
      {"d.cif:22: _atom_site.id '9999", "of atom 2 starts with a number that " + range});
  expect_input_error(
      [&] { read_atoms(write_text("e.cif", with_atom_field(head, 2, 14, "2147483648"))); },
      {"e.cif:22: _atom_site.pdbx_formal_charge '2147483648' of atom 2 " + range});
  // Not a number where gemmi parses an int: it threw "not an integer: abc", with no line.
  expect_input_error([&] { read_atoms(write_text("f.cif", with_atom_field(head, 3, 14, "abc"))); },
                     {"f.cif:23: _atom_site.pdbx_formal_charge 'abc' of atom 3 is not an integer"});
  expect_input_error([&] { read_atoms(write_text("g.cif", with_atom_field(head, 1, 7, "1.5"))); },
                     {"g.cif:21: _atom_site.label_seq_id '1.5' of atom 1 is not an integer"});
  // Columns of other categories, as a loop and as tag-value pairs (the tag's line).
  expect_input_error(
      [&] {
        read_atoms(write_text("h.cif", head + "loop_\n_entity_poly_seq.entity_id\n"
                                              "_entity_poly_seq.num\n_entity_poly_seq.mon_id\n"
                                              "1 1 ILE\n1 -99999999999999 ALA\n"));
      },
      {"h.cif:31: _entity_poly_seq.num '-99999999999999' of row 2 " + range});
  expect_input_error(
      [&] {
        read_atoms(write_text("i.cif", head + "_exptl.method 'X-RAY DIFFRACTION'\n"
                                              "_exptl.crystals_number 99999999999999\n"));
      },
      {"i.cif:27: _exptl.crystals_number '99999999999999' of row 1 " + range});
}

TEST(Structure, MmcifAssemblyOperatorRangesAreBounded) {
  // gemmi expands "(1-60)" into 60 operator names one by one, counting with an int: a range
  // of 2e9 listed gigabytes of strings (bad_alloc: exit 70) and one ending at 2147483647 never
  // stopped (signed overflow). Real assemblies list dozens.
  const auto assembly = [](const std::string& operators) {
    return mmcif_head() +
           "_pdbx_struct_assembly.id 1\n_pdbx_struct_assembly.details author_defined_assembly\n"
           "_pdbx_struct_assembly.method_details ?\n_pdbx_struct_assembly.oligomeric_details "
           "monomeric\n_pdbx_struct_assembly.oligomeric_count 1\n"
           "_pdbx_struct_assembly_gen.assembly_id 1\n_pdbx_struct_assembly_gen.oper_expression " +
           operators + "\n_pdbx_struct_assembly_gen.asym_id_list poly\n";
  };
  EXPECT_EQ(read_atoms(write_text("icosahedral.cif", assembly("'(1-60)'"))).size(), 5u);
  EXPECT_EQ(read_atoms(write_text("list.cif", assembly("1,3-5,X"))).size(), 5u);
  expect_input_error([&] { read_atoms(write_text("a.cif", assembly("'(1-2000000000)'"))); },
                     {"a.cif:32: _pdbx_struct_assembly_gen.oper_expression '(1-2000000000)' of "
                      "row 1 lists more than 1000000 operators"});
  expect_input_error(
      [&] { read_atoms(write_text("b.cif", assembly("2147483647-2147483647"))); },
      {"b.cif:32: _pdbx_struct_assembly_gen.oper_expression", "from 0 to 2147483646"});
  expect_input_error([&] { read_atoms(write_text("c.cif", assembly("1-99999999999"))); },
                     {"c.cif:32:", "from 0 to 2147483646"});
}

TEST(Structure, TruncatedGzipIsAnInputError) {
  const std::string text = testing::slurp(kData / "1a1p.pdb");
  const auto gz = testing::test_dir() / "cut.pdb.gz";
  gzFile out = gzopen(gz.string().c_str(), "wb");
  gzwrite(out, text.data(), static_cast<unsigned>(text.size()));
  gzclose(out);
  std::string bytes = testing::slurp(gz);
  bytes.resize(bytes.size() / 2);
  write_text("cut.pdb.gz", bytes);
  expect_input_error([&] { read_atoms(gz); }, {"cut.pdb.gz", "gzip"});
}

const char* kIronPdb =
    "HETATM    1 FE   HEM A 200      10.000  10.000  10.000  1.00  0.00          FE  \n"
    "HETATM    2  NA  HEM A 200      11.000  10.000  10.000  1.00  0.00           N  \n";

TEST(Structure, ElementWithoutRadiusNamesTheLine) {
  const auto path = write_text("heme.pdb", std::string("REMARK test\n") + kIronPdb);
  expect_input_error([&] { read_atoms(path); }, {"heme.pdb:2:", "FE", "`radii_file`"});
  AtomReadOptions protein_only;
  protein_only.include_hetatm = false;
  expect_input_error([&] { read_atoms(path, protein_only); }, {"excluded"});
}

TEST(Structure, UserRadiusTableOverridesAndCompletes) {
  const auto pdb = write_text("heme.pdb", kIronPdb);
  const auto table = write_text("radii.txt",
                                "# element and residue/atom entries\n"
                                "FE 1.40\n"
                                "HEM NA 1.65   # more specific than the element\n");
  AtomReadOptions options;
  options.radii_file = table;
  const Atoms atoms = read_atoms(pdb, options);
  ASSERT_EQ(atoms.size(), 2u);
  EXPECT_DOUBLE_EQ(atoms[0].radius, 1.40);
  EXPECT_DOUBLE_EQ(atoms[1].radius, 1.65);
  // For PQR, the table replaces the file's radii where it matches.
  const auto pqr = write_text("x.pqr", "ATOM 1 NA HEM 1 0 0 0 0 1.0\nATOM 2 C HEM 1 1 0 0 0 1.9\n");
  const Atoms q = read_atoms(pqr, options);
  EXPECT_DOUBLE_EQ(q[0].radius, 1.65);
  EXPECT_DOUBLE_EQ(q[1].radius, 1.9);
}

TEST(RadiusTable, LookupPrecedenceAndWildcards) {
  const auto path = write_text("t.txt", "ARG NH1 1.50\n* NH1 1.60\nARG * 1.70\nn 1.80\n* 2.00\n");
  const RadiusTable t = read_radius_table(path);
  Atom a;
  a.residue_name = "arg";
  a.atom_name = "NH1";
  a.element = "N";
  EXPECT_DOUBLE_EQ(*t.lookup(a), 1.50);
  a.residue_name = "LYS";
  EXPECT_DOUBLE_EQ(*t.lookup(a), 1.60);
  a.atom_name = "NZ";
  EXPECT_DOUBLE_EQ(*t.lookup(a), 1.80);
  a.element = "C";
  EXPECT_DOUBLE_EQ(*t.lookup(a), 2.00);
  a.residue_name = "ARG";
  EXPECT_DOUBLE_EQ(*t.lookup(a), 1.70);
  EXPECT_FALSE(builtin_radius_table().lookup(Atom{}).has_value());
}

TEST(RadiusTable, Errors) {
  expect_input_error([] { read_radius_table(write_text("a.txt", "C 1.7\nARG NH1\n")); },
                     {"a.txt:2:", "radius 'NH1' is not a finite number"});
  expect_input_error([] { read_radius_table(write_text("b.txt", "C 1 2 3\n")); },
                     {"b.txt:1:", "expected"});
  expect_input_error([] { read_radius_table(write_text("c.txt", "C -1.7\n")); },
                     {"c.txt:1:", ">= 0"});
  expect_input_error([] { read_radius_table(write_text("d.txt", "C 1.7\nc 1.8\n")); },
                     {"d.txt:2:", "duplicate"});
  expect_input_error([] { read_radius_table(write_text("e.txt", "# nothing\n")); },
                     {"e.txt", "no entries"});
  expect_input_error([] { read_radius_table(write_text("f.txt", "C inf\n")); },
                     {"f.txt:1:", "finite"});
}

TEST(Structure, MalformedPdbIsAnInputError) {
  const auto path =
      write_text("bad.pdb", "ATOM      1  N   ILE     1      -7.1x8   5.359   0.606  1.00  0.00\n");
  expect_input_error([&] { read_atoms(path); }, {"bad.pdb:1:", "x coordinate '-7.1x8'"});
  expect_input_error([] { read_atoms(write_text("none.pdb", "REMARK nothing\nEND\n")); },
                     {"none.pdb", "no ATOM"});
  expect_input_error(
      [] { read_atoms(write_text("bad.cif", "data_x\nloop_\n_a.b\n'unterminated\n")); },
      {"bad.cif", "mmCIF"});
}

}  // namespace
}  // namespace molmesh
