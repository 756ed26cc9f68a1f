"""molmesh.hierarchy and molmesh.read_hierarchy against `molmesh hierarchy` on the same
molecule: the same meshes on every level and the same prolongations, bit for bit."""
import numpy as np
import pytest

import molmesh
from conftest import DATA, read_json, run_cli

T0 = [0.1, 0.3, 0.5]


@pytest.fixture(scope="module")
def cli_file(tmp_path_factory):
    out = tmp_path_factory.mktemp("hierarchy")
    run_cli("hierarchy", DATA / "1a1p.pqr", "-o", out / "h.h5", "--t0", ",".join(map(str, T0)),
            "--domain", "exterior", "--stats", out / "h.json")
    return out / "h.h5"


@pytest.fixture(scope="module")
def built():
    return molmesh.hierarchy(molmesh.read_atoms(DATA / "1a1p.pqr"), t0=T0, domain="exterior")


def assert_same_tetmesh(a, b):
    for name in ["vertices", "tetrahedra", "cell_markers", "vertex_markers", "boundary_faces",
                 "boundary_face_markers"]:
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


def assert_same_csr(a, b):
    assert a.shape == b.shape
    assert np.array_equal(a.indptr, b.indptr) and np.array_equal(a.indices, b.indices)
    assert np.array_equal(a.data, b.data)


def test_hierarchy_is_the_clis_bit_for_bit(built, cli_file):
    cli = molmesh.read_hierarchy(cli_file)
    assert len(built) == len(cli) == 3
    for mine, theirs in zip(built.levels, cli.levels):
        assert mine.t0 == theirs.t0
        assert np.array_equal(mine.surface.vertices, theirs.surface.vertices)
        assert np.array_equal(mine.surface.faces, theirs.surface.faces)
        assert np.array_equal(mine.surface_provenance, theirs.surface_provenance)
        assert np.array_equal(mine.volume_permutation, theirs.volume_permutation)
        assert_same_tetmesh(mine.volume, theirs.volume)
    for p, q in zip(built.prolongations + built.surface_prolongations,
                    cli.prolongations + cli.surface_prolongations):
        assert_same_csr(p, q)
    assert cli.parameters["domain"] == "exterior" and cli.input_name == "1a1p.pqr"


def test_parameters_are_the_clis(built, cli_file):
    """The same options give the same recorded parameters and provenance, key for key."""
    cli = molmesh.read_hierarchy(cli_file)
    assert built.parameters == cli.parameters
    assert built.parameters["t0"] == "0.1,0.3,0.5"
    assert (built.input_name, built.input_checksum) == (cli.input_name, cli.input_checksum)


def test_report_is_the_clis_stats(built, cli_file):
    """Hierarchy.report has the keys of `molmesh hierarchy --stats` (pipeline/report_json.hpp)
    and the same TetGen runs; the CLI adds its input, its parameters are the file's."""
    cli = read_json(cli_file.with_suffix(".json"))
    assert set(built.report) == set(cli) - {"input"}
    assert len(built.report["levels"]) == len(cli["levels"]) == len(T0)
    for mine, theirs in zip(built.report["levels"], cli["levels"]):
        assert set(mine) == set(theirs) and set(mine["tetgen"]) == set(theirs["tetgen"])
        assert mine["tetgen"]["switches"] == theirs["tetgen"]["switches"]
        assert mine["bandwidth_after"] == theirs["bandwidth_after"]
        assert mine["volume_transfer"] == theirs["volume_transfer"]
    assert built.report["outer_radius"] == cli["outer_radius"] > 0
    assert cli["parameters"] == molmesh.read_hierarchy(cli_file).parameters
    assert built.report["parameters"] == cli["parameters"] == built.parameters


def test_non_default_parameters_are_the_clis(tmp_path):
    """Options away from their defaults, an active-site file and the atom selection are
    recorded as the CLI records them."""
    atoms = molmesh.read_atoms(DATA / "1a1p.pqr", hetatm=False, waters=True)
    centre = atoms.positions.mean(axis=0)
    site = tmp_path / "site.txt"
    site.write_text(f"{centre[0]} {centre[1]} {centre[2]} 4\n")
    run_cli("hierarchy", DATA / "1a1p.pqr", "-o", tmp_path / "h.h5", "--t0", "0.2",
            "--domain", "interior", "--no-hetatm", "--waters", "--active-site", site,
            "--spacing", "0.6", "--max-volume", "20", "--size-growth", "2", "--no-renumber",
            "--alpha", "1.5")
    mine = molmesh.hierarchy(atoms, t0=[0.2], domain="interior", active_site=site, spacing=0.6,
                             max_volume=20.0, size_growth=2.0, renumber=False, alpha=1.5)
    cli = molmesh.read_hierarchy(tmp_path / "h.h5")
    assert mine.parameters == cli.parameters
    assert mine.parameters["hetatm"] == "no" and mine.parameters["active_site"] == str(site)
    assert mine.parameters["max_volume"] == "20" and mine.parameters["renumbering"] == "none"


def test_prolongations_are_scipy_csr_matching_h5py(built, cli_file):
    h5py = pytest.importorskip("h5py")
    import scipy.sparse

    with h5py.File(cli_file, "r") as f:
        for i, p in enumerate(built.prolongations):
            assert isinstance(p, scipy.sparse.csr_matrix)
            g = f[f"/transfer/{i + 1}_to_{i}/volume"]
            q = scipy.sparse.csr_matrix((g["data"][:], g["indices"][:], g["indptr"][:]),
                                        shape=tuple(g.attrs["shape"]))
            assert_same_csr(p, q)
            fine, coarse = built.levels[i].volume, built.levels[i + 1].volume
            assert p.shape == (len(fine.vertices), len(coarse.vertices))
            np.testing.assert_allclose(p.sum(axis=1), 1.0, rtol=1e-12)  # rows sum to 1


def test_write_and_read_back(tmp_path, built):
    built.write(tmp_path / "mine.h5")
    back = molmesh.read_hierarchy(tmp_path / "mine.h5")
    for a, b in zip(built.levels, back.levels):
        assert_same_tetmesh(a.volume, b.volume)
    assert back.parameters == built.parameters and back.parameters["domain"] == "exterior"
    field = np.arange(len(back.levels[0].volume.vertices), dtype=float)
    molmesh.write_point_field(tmp_path / "mine.h5", 0, "index", field)
    assert molmesh.point_field_names(tmp_path / "mine.h5", 0) == ["index"]
    np.testing.assert_array_equal(molmesh.read_point_field(tmp_path / "mine.h5", 0, "index"), field)
    # Several at once: all or none.
    molmesh.write_point_fields(tmp_path / "mine.h5", 0, {"twice": 2 * field, "neg": -field})
    assert molmesh.point_field_names(tmp_path / "mine.h5", 0) == ["index", "neg", "twice"]
    np.testing.assert_array_equal(molmesh.read_point_field(tmp_path / "mine.h5", 0, "neg"), -field)
    with pytest.raises(molmesh.Error):
        molmesh.write_point_fields(tmp_path / "mine.h5", 0, {"ok": field, "short": field[:3]})
    assert "ok" not in molmesh.point_field_names(tmp_path / "mine.h5", 0)
    meshio = pytest.importorskip("meshio")
    m = meshio.read(tmp_path / "mine_L0_volume.xdmf")
    assert len(m.points) == len(field)


def test_views_keep_the_hierarchy_alive(cli_file):
    import gc

    def coarsest_vertices():
        h = molmesh.read_hierarchy(cli_file)
        view = h.levels[-1].volume.vertices
        return view, view.copy()  # h, its level and its mesh go out of scope here

    view, copy = coarsest_vertices()
    gc.collect()
    molmesh.read_hierarchy(cli_file)  # reuse freed memory, if any was freed
    assert np.array_equal(view, copy)


def test_not_a_hierarchy_is_an_input_error(tmp_path):
    bogus = tmp_path / "x.h5"
    bogus.write_text("not hdf5\n")
    with pytest.raises(molmesh.InputError) as info:
        molmesh.read_hierarchy(bogus)
    assert info.value.file == str(bogus)


def test_size_growth_range_is_the_libraries(tmp_path, built):
    """The library refuses a size growth outside [1, 10] (HierarchyOptions::validate), for
    Python as for the CLI, which checks the same bounds while parsing (exit 2)."""
    surface = built.levels[0].surface
    for beyond in [0.999, 10.001]:
        with pytest.raises(molmesh.Error, match="`size_growth`.*\\[1, 10\\]"):
            molmesh.hierarchy(surface, size_growth=beyond)
        run_cli("hierarchy", DATA / "1a1p.pqr", "-o", tmp_path / "h.h5", "--size-growth", beyond,
                expect=2)
    assert not (tmp_path / "h.h5").exists()


def test_keep_spheres_is_the_clis(tmp_path):
    """keep_spheres= keeps a region dense on every level as `molmesh hierarchy --keep-spheres`
    does (default: none, SurfacePipelineOptions'): the same levels bit for bit and the same
    recorded parameters; an array keeps the same vertices as the file."""
    atoms = molmesh.read_atoms(DATA / "1a1p.pqr")
    # Around the atom farthest from the centre, so the sphere holds surface vertices.
    positions = atoms.positions
    far = positions[np.argmax(np.linalg.norm(positions - positions.mean(axis=0), axis=1))]
    spheres = tmp_path / "keep.txt"
    spheres.write_text(f"{far[0]} {far[1]} {far[2]} 6\n")
    run_cli("hierarchy", DATA / "1a1p.pqr", "-o", tmp_path / "h.h5", "--t0", "0.2,0.6",
            "--domain", "interior", "--keep-spheres", spheres)
    cli = molmesh.read_hierarchy(tmp_path / "h.h5")
    assert molmesh.defaults("hierarchy")["keep_spheres"] is None
    from_file = molmesh.hierarchy(atoms, t0=[0.2, 0.6], domain="interior", keep_spheres=spheres)
    from_array = molmesh.hierarchy(atoms, t0=[0.2, 0.6], domain="interior",
                                   keep_spheres=molmesh.read_spheres(spheres))
    plain = molmesh.hierarchy(atoms, t0=[0.2, 0.6], domain="interior")
    for mine, array, theirs in zip(from_file.levels, from_array.levels, cli.levels):
        assert np.array_equal(mine.surface.vertices, theirs.surface.vertices)
        assert np.array_equal(array.surface.vertices, theirs.surface.vertices)
        assert_same_tetmesh(mine.volume, theirs.volume)
    assert from_file.parameters == cli.parameters
    assert cli.parameters["keep_spheres"] == str(spheres)
    # The spheres matter: without them the coarse level has fewer surface vertices.
    assert len(plain.levels[-1].surface.vertices) < len(cli.levels[-1].surface.vertices)
