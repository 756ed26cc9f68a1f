"""molmesh.read_atoms and molmesh.Atoms: file reading with the CLI's selection options,
atoms from arrays, errors with file and line."""
import numpy as np
import pytest

import molmesh
from conftest import DATA


def test_read_pqr_gives_positions_radii_and_charges(fas2_atoms):
    atoms = fas2_atoms
    assert len(atoms) == 906
    assert atoms.positions.shape == (906, 3) and atoms.positions.dtype == np.float64
    # First record of fas2.pqr: "N NTE 544 -13.336 3.045 35.885 0.185 1.824"
    np.testing.assert_array_equal(atoms.positions[0], [-13.336, 3.045, 35.885])
    assert atoms.charges[0] == 0.185 and atoms.radii[0] == 1.824
    assert atoms.atom_names[0] == "N" and atoms.residue_names[0] == "NTE"
    assert atoms.residue_numbers[0] == 544
    assert np.isnan(atoms.blobbyness).all()
    assert abs(atoms.charges.sum()) < 1e3


def test_pdb_radii_come_from_the_table_and_hydrogens_can_be_dropped():
    with_h = molmesh.read_atoms(DATA / "1a1p.pdb")
    without_h = molmesh.read_atoms(DATA / "1a1p.pdb", hydrogens=False)
    assert len(without_h) < len(with_h)
    assert (with_h.radii > 0).all()


def test_atoms_from_arrays_mesh_like_the_file(fas2_atoms):
    copy = molmesh.Atoms(fas2_atoms.positions, fas2_atoms.radii, charges=fas2_atoms.charges)
    np.testing.assert_array_equal(copy.positions, fas2_atoms.positions)
    a = molmesh.surface(fas2_atoms, raw=True, spacing=1.0)
    b = molmesh.surface(copy, raw=True, spacing=1.0)
    np.testing.assert_array_equal(a.vertices, b.vertices)
    np.testing.assert_array_equal(a.faces, b.faces)


def test_per_atom_blobbyness_changes_the_surface(fas2_atoms):
    n = len(fas2_atoms)
    blobby = molmesh.Atoms(fas2_atoms.positions, fas2_atoms.radii, blobbyness=np.full(n, -2.0))
    assert (blobby.blobbyness == -2.0).all()
    a = molmesh.surface(fas2_atoms, surface="gaussian", raw=True, spacing=1.0).stats()
    b = molmesh.surface(blobby, surface="gaussian", raw=True, spacing=1.0).stats()
    assert b["area"] != a["area"]


def test_bad_arrays_are_value_errors():
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        molmesh.Atoms(np.zeros((4, 2)), np.ones(4))
    with pytest.raises(ValueError, match="radii has 3 values for 4"):
        molmesh.Atoms(np.zeros((4, 3)), np.ones(3))
    with pytest.raises(ValueError, match="finite"):
        molmesh.Atoms([[0, 0, np.nan]], [1.0])


def test_malformed_file_raises_input_error_with_file_and_line(tmp_path):
    bad = tmp_path / "bad.pqr"
    lines = (DATA / "fas2.pqr").read_text().splitlines()[:5]
    lines[2] = "ATOM      3  HT2 NTE   544     -13.827   3.513  36.633  0.190"  # no radius
    bad.write_text("\n".join(lines) + "\n")
    with pytest.raises(molmesh.InputError) as info:
        molmesh.read_atoms(bad)
    error = info.value
    assert isinstance(error, ValueError) and isinstance(error, molmesh.Error)
    assert error.file == str(bad) and error.line == 3
    assert str(error).startswith(f"{bad}:3:")


def test_missing_file_raises_input_error_without_line(tmp_path):
    with pytest.raises(molmesh.InputError) as info:
        molmesh.read_atoms(tmp_path / "absent.pqr")
    assert info.value.file == str(tmp_path / "absent.pqr") and info.value.line is None


def test_zero_radii_warn(tmp_path):
    pqr = tmp_path / "zero.pqr"
    pqr.write_text("ATOM      1  N   ALA     1       0.000   0.000   0.000  0.0 1.5\n"
                   "ATOM      2  H   ALA     1       1.000   0.000   0.000  0.0 0.0\n")
    with pytest.warns(molmesh.Warning, match="zero radius"):
        molmesh.read_atoms(pqr)


def test_unknown_keyword_is_a_type_error():
    with pytest.raises(TypeError, match="hetatms"):
        molmesh.read_atoms(DATA / "fas2.pqr", hetatms=False)
    assert set(molmesh.defaults("read_atoms")) == {"radii", "hetatm", "waters", "hydrogens"}
