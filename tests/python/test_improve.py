"""molmesh.improve against `molmesh improve` on the same user mesh."""
import numpy as np
import pytest

import molmesh
from conftest import DATA, read_json, run_cli


@pytest.fixture(scope="module")
def raw_ply(tmp_path_factory):
    out = tmp_path_factory.mktemp("improve")
    run_cli("surface", DATA / "1a1p.pqr", "-o", out / "raw.ply", "--raw")
    return out / "raw.ply"


def test_improve_is_the_clis_bit_for_bit(tmp_path, raw_ply):
    run_cli("improve", raw_ply, "-o", tmp_path / "cli.ply", "--stats", tmp_path / "cli.json")
    mine = molmesh.improve(molmesh.read_surface(raw_ply))
    cli = molmesh.read_surface(tmp_path / "cli.ply")
    assert np.array_equal(mine.vertices, cli.vertices)
    assert np.array_equal(mine.faces, cli.faces)
    stats = read_json(tmp_path / "cli.json")
    assert mine.raw.stats() == stats["input"]["input_surface"]
    assert mine.report["repair"] == stats["input"]["repair"]
    assert mine.report["parameters"]["feature_weight"] == stats["parameters"]["feature_weight"]
    assert mine.report["parameters"] == stats["parameters"]  # pipeline/parameters_json.hpp


def test_improve_options_and_arrays(tmp_path, raw_ply):
    run_cli("improve", raw_ply, "-o", tmp_path / "cli.ply", "--t0", "0.3", "--sweeps", "4",
            "--no-flips", "--stats", tmp_path / "cli.json")
    raw = molmesh.read_surface(raw_ply)
    mine = molmesh.improve(raw.vertices, raw.faces, t0=[0.3], sweeps=4, flips=False)
    cli = molmesh.read_surface(tmp_path / "cli.ply")
    assert np.array_equal(mine.vertices, cli.vertices)
    assert np.array_equal(mine.faces, cli.faces)
    assert mine.report["parameters"] == read_json(tmp_path / "cli.json")["parameters"]
    assert mine.report["parameters"]["flips"] is False


def test_open_mesh_is_refused_with_a_molmesh_error(raw_ply):
    raw = molmesh.read_surface(raw_ply)
    with pytest.raises(molmesh.Error, match="hole"):
        molmesh.improve(raw.vertices, raw.faces[:-10])


def test_repairs_are_reported_and_warned(raw_ply):
    raw = molmesh.read_surface(raw_ply)
    faces = np.vstack([raw.faces, raw.faces[:1]])  # one duplicate triangle
    with pytest.warns(molmesh.Warning, match="repaired"):
        out = molmesh.improve(raw.vertices, faces, repair_only=True)
    assert out.report["repair"]["duplicate_faces"] == 1
    assert np.array_equal(out.faces, out.raw.faces)
