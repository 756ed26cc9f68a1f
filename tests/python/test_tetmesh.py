"""molmesh.tetmesh against `molmesh tetmesh` on the same molecule."""
import numpy as np
import pytest

import molmesh
from conftest import DATA, read_json, run_cli


@pytest.fixture(scope="module")
def atoms():
    return molmesh.read_atoms(DATA / "1a1p.pqr")


@pytest.fixture(scope="module")
def cli_full(tmp_path_factory):
    out = tmp_path_factory.mktemp("tetmesh")
    run_cli("tetmesh", DATA / "1a1p.pqr", "-o", out / "t.m", "--stats", out / "t.json",
            "--surface-output", out / "s.ply")
    return molmesh.read_tetmesh(out / "t.m"), read_json(out / "t.json"), out


@pytest.fixture(scope="module")
def full(atoms):
    return molmesh.tetmesh(atoms)


def test_tetmesh_is_the_clis(full, cli_full):
    cli_mesh, cli_stats, out = cli_full
    stats = full.stats()
    # Every quality number agrees to the last bit (they are computed from the mesh).
    assert stats == {k: cli_stats[k] for k in stats}
    tetgen = dict(full.report["tetgen"], seconds=None)
    assert tetgen == dict(cli_stats["tetgen"], seconds=None)
    # The same keys: TetMesh.stats() is the --stats document's metrics (io/stats_json.hpp),
    # report["tetgen"] its tetgen object; the CLI adds domain, timings, input, parameters.
    assert set(stats) | {"tetgen", "domain", "timings_s", "input", "parameters"} == set(cli_stats)
    assert np.array_equal(full.tetrahedra, cli_mesh.tetrahedra)
    assert np.array_equal(full.cell_markers, cli_mesh.cell_markers)
    # MCSF stores 11 significant digits.
    np.testing.assert_allclose(full.vertices, cli_mesh.vertices, rtol=1e-9, atol=1e-9)
    surface = molmesh.read_surface(out / "s.ply")
    assert np.array_equal(full.report["surface"].vertices, surface.vertices)
    # report["parameters"] is the --stats parameters object (pipeline/parameters_json.hpp).
    assert full.report["parameters"] == cli_stats["parameters"]


def test_arrays_and_markers(full):
    assert full.vertices.dtype == np.float64 and full.vertices.shape[1] == 3
    assert full.tetrahedra.dtype == np.int32 and full.tetrahedra.shape[1] == 4
    assert set(np.unique(full.cell_markers)) == {1, 2}
    assert set(np.unique(full.boundary_face_markers)) <= {1, 2, 3}
    assert len(full.vertex_markers) == len(full.vertices)


def test_surface_input_with_atoms_is_the_same_mesh(atoms, full):
    again = molmesh.tetmesh(full.report["surface"], atoms)
    assert np.array_equal(again.tetrahedra, full.tetrahedra)
    assert np.array_equal(again.vertices, full.vertices)
    # A given surface records the tetmesh options only, as the CLI does for a mesh file.
    assert "spacing" not in again.report["parameters"]
    assert again.report["parameters"] == {
        k: v for k, v in full.report["parameters"].items() if k in again.report["parameters"]}


def test_surface_file_parameters_are_the_clis(tmp_path, cli_full):
    _, _, out = cli_full
    run_cli("tetmesh", out / "s.ply", "-o", tmp_path / "s.m", "--domain", "interior",
            "--max-volume", "30", "--stats", tmp_path / "s.json")
    mesh = molmesh.tetmesh(molmesh.read_surface(out / "s.ply"), domain="interior",
                           max_volume=30.0)
    assert mesh.report["parameters"] == read_json(tmp_path / "s.json")["parameters"]
    assert mesh.report["parameters"]["max_volume"] == 30.0


def test_exterior_options(tmp_path, atoms):
    run_cli("tetmesh", DATA / "1a1p.pqr", "-o", tmp_path / "e.m", "--domain", "exterior",
            "--sphere-ratio", "10", "--stats", tmp_path / "e.json", "--spacing", "0.8")
    mesh = molmesh.tetmesh(atoms, domain="exterior", sphere_ratio=10, spacing=0.8)
    cli = read_json(tmp_path / "e.json")
    assert mesh.stats() == {k: cli[k] for k in mesh.stats()}
    assert mesh.report["parameters"]["spacing"] == 0.8
    assert mesh.report["parameters"] == cli["parameters"]
    assert mesh.report["parameters"]["domain"] == "exterior"
    assert set(np.unique(mesh.cell_markers)) == {2}


def test_meshio_conversion_and_vtu(tmp_path, full):
    meshio = pytest.importorskip("meshio")
    m = full.to_meshio(point_data={"x": full.vertices[:, 0].copy()})
    assert len(m.cells_dict["tetra"]) == len(full.tetrahedra)
    meshio.write(tmp_path / "m.vtu", m)
    full.write(tmp_path / "w.vtu", point_fields={"x": full.vertices[:, 0]})
    back = meshio.read(tmp_path / "w.vtu")
    np.testing.assert_array_equal(back.cells_dict["tetra"], full.tetrahedra)
    np.testing.assert_allclose(back.point_data["x"], full.vertices[:, 0], rtol=1e-8)


def test_open_surface_is_an_error(full):
    s = full.report["surface"]
    holed = molmesh.Surface(s.vertices, s.faces[:-20])
    with pytest.raises(molmesh.Error):
        molmesh.tetmesh(holed)


def test_option_errors_name_the_keyword(full):
    """The library names its own option (max_radius_edge_ratio); Python says the keyword."""
    with pytest.raises(molmesh.Error, match="`max_radius_edge`") as info:
        molmesh.tetmesh(full.report["surface"], max_radius_edge=0.5)
    assert "--" not in str(info.value) and "max_radius_edge_ratio" not in str(info.value)
    with pytest.raises(molmesh.Error, match="`size_factor`"):
        molmesh.tetmesh(full.report["surface"], size_factor=-1.0)


def test_defaults_and_ranges_are_the_clis(tmp_path, cli_full):
    """Both front ends take the defaults and ranges of TetMeshOptions (tetrahedralize.hpp):
    the CLI's --stats parameters are Python's defaults, and a value just beyond a bound is
    refused by both (the CLI while parsing, exit 2)."""
    _, cli_stats, out = cli_full
    defaults, cli = molmesh.defaults("tetmesh"), cli_stats["parameters"]
    assert defaults["domain"] == cli["domain"] == "full"
    for keyword, key in [("sphere_ratio", "sphere_ratio"), ("size_factor", "size_factor"),
                         ("surface_size_ratio", "surface_size_ratio"),
                         ("sphere_subdivisions", "outer_sphere_subdivisions"),
                         ("max_radius_edge", "max_radius_edge_ratio"),
                         ("min_dihedral", "min_dihedral_deg")]:
        assert defaults[keyword] == cli[key], keyword
    surface = molmesh.read_surface(out / "s.ply")
    for keyword, flag, beyond in [("sphere_ratio", "--sphere-ratio", 1.0001e4),
                                  ("sphere_subdivisions", "--sphere-subdivisions", 8),
                                  ("max_radius_edge", "--max-radius-edge", 0.999),
                                  ("min_dihedral", "--min-dihedral", 70.001),
                                  ("size_factor", "--size-factor", 1000.001),
                                  ("surface_size_ratio", "--surface-size-ratio", 100.001)]:
        with pytest.raises(molmesh.Error, match=f"`{keyword}`"):
            molmesh.tetmesh(surface, **{keyword: beyond})
        run_cli("tetmesh", out / "s.ply", "-o", tmp_path / "x.m", flag, beyond, expect=2)


# Keywords the CLI spells otherwise, and keywords no command-line flag has.
CLI_FLAGS = {"flips": "--no-flips"}
PYTHON_ONLY = {"truncation", "keep_volume", "measure"}


@pytest.mark.parametrize("function, commands, everywhere", [
    ("tetmesh", ["tetmesh", "hierarchy"], True),
    ("surface", ["surface", "improve"], False),
    ("improve", ["improve", "surface"], False),
])
def test_help_texts_are_the_clis(function, commands, everywhere):
    """Each keyword's docstring and its CLI flag's help are one text, the library's option
    tables (tetmesh/tetmesh_option_specs.hpp, pipeline/surface_option_specs.hpp,
    processing/processing_option_specs.hpp, pipeline/improve_option_specs.hpp), in every
    command that has the flag: tetmesh's in `tetmesh --help` and `hierarchy --help` alike;
    surface's and improve's processing options each in the command that has them (`surface`
    has no --sweeps, `improve` no --alpha)."""
    import re
    lines = {line.strip().split(" = ")[0]: line.strip()
             for line in getattr(molmesh, function).__doc__.splitlines() if " = " in line}
    helps = {command: run_cli(command, "--help").stdout for command in commands}
    checked = 0
    for keyword in molmesh.defaults(function):
        if keyword in PYTHON_ONLY:
            continue
        text = lines[keyword].split(": ", 1)[1]
        # Python names other options as keywords, the CLI as flags.
        text = re.sub(r"`(\w+)`", lambda m: "--" + m[1].replace("_", "-"), text)[:40]
        flag = CLI_FLAGS.get(keyword, "--" + keyword.replace("_", "-"))
        having = [c for c in commands if re.search(re.escape(flag) + r"\b", helps[c])]
        if everywhere and not (keyword == "tetgen_switches"):
            assert having == commands, (keyword, having)
        assert having, (function, keyword, flag)
        for command in having:
            assert text in helps[command], (command, keyword, text)
            checked += 1
    assert checked >= 10, checked
