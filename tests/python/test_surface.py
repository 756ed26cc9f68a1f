"""molmesh.surface against `molmesh surface` on the same input: the same vertices and
faces bit for bit, the same --stats numbers; options, volumes, progress and aborts."""
import os
import signal

import numpy as np
import pytest

import molmesh
from conftest import DATA, read_json, run_cli

STATS_KEYS = ["vertices", "triangles", "min_angle_deg", "max_angle_deg",
              "angle_histogram_percent", "fraction_angles_40_80", "area", "volume",
              "components", "euler_characteristic", "closed", "manifold"]


def assert_same_mesh(a, b):
    assert a.vertices.shape == b.vertices.shape
    assert np.array_equal(a.vertices, b.vertices)  # bit for bit (PLY stores float64)
    assert np.array_equal(a.faces, b.faces)


def test_default_surface_is_the_clis_bit_for_bit(fas2_surface, fas2_cli_surface):
    cli_mesh, cli_stats = fas2_cli_surface
    surf = fas2_surface
    assert surf.vertices.dtype == np.float64 and surf.vertices.shape[1] == 3
    assert surf.faces.dtype == np.int32 and surf.faces.shape[1] == 3
    assert_same_mesh(surf, cli_mesh)
    stats = surf.stats()
    assert {k: stats[k] for k in STATS_KEYS} == {k: cli_stats[k] for k in STATS_KEYS}
    assert surf.raw.stats() == cli_stats["input"]["raw_surface"]
    assert list(surf.report["grid_dims"]) == cli_stats["input"]["grid_dims"]
    assert [s["name"] for s in surf.report["stages"]] == [s["name"] for s in cli_stats["stages"]]
    assert [s["stats"] for s in surf.report["stages"]] == [s["stats"] for s in cli_stats["stages"]]
    assert surf.report["dislocation_max"] == cli_stats["dislocation_max"]
    # Only the Gaussian reports its distance to Eq. 1's level set; the default SES has none.
    assert "levelset_distance_max" not in surf.report and "levelset_distance_max" not in cli_stats


def test_unmeasured_surface_is_the_same_without_stage_stats(fas2_surface, fas2_atoms):
    """measure=False (the CLI without --stats) skips the per-stage stats and distances, and
    only those: the surface is the same bit for bit, .stats() still works."""
    surf = molmesh.surface(fas2_atoms, measure=False)
    assert_same_mesh(surf, fas2_surface)
    assert surf.stats() == fas2_surface.stats()
    assert all(s["stats"] is None for s in surf.report["stages"])
    assert "levelset_distance_max" not in surf.report
    assert molmesh.defaults("surface")["measure"] is True


def test_stats_keys_are_the_clis(fas2_surface, fas2_cli_surface):
    """Surface.stats() and .report together have the keys of `--stats` (one writer each:
    io/stats_json.hpp, pipeline/report_json.hpp); the CLI adds its run's timings and input."""
    _, cli_stats = fas2_cli_surface
    surf = fas2_surface
    python_keys = set(surf.stats()) | (set(surf.report) - {"grid_dims", "parameters", "volume"})
    assert python_keys | {"timings_s", "input", "parameters"} == set(cli_stats)
    assert set(surf.stats()) == set(STATS_KEYS)
    assert [set(s) for s in surf.report["stages"]] == [set(s) for s in cli_stats["stages"]]


def test_defaults_are_the_clis(fas2_cli_surface):
    """The keyword defaults and the parameters the CLI reports come from one struct."""
    _, cli_stats = fas2_cli_surface
    defaults = molmesh.defaults("surface")
    cli = cli_stats["parameters"]
    for name in ["surface", "probe_radius", "spacing", "blobbyness", "isovalue", "min_cavity_volume", "blur", "coarsen",
                 "rings", "alpha", "beta", "raw"]:
        assert defaults[name] == cli[name], name
    assert defaults["truncation"] == cli["kernel_truncation"]


def test_parameters_are_the_clis(fas2_surface, fas2_cli_surface):
    """report["parameters"] is the --stats parameters object, key for key and value for value
    (one writer: pipeline/parameters_json.hpp): keep_on_surface resolved, the atom selection."""
    _, cli_stats = fas2_cli_surface
    assert fas2_surface.report["parameters"] == cli_stats["parameters"]
    # The default surface is the SES, whose processing moves stay off its level set.
    assert fas2_surface.report["parameters"]["surface"] == "ses"
    assert fas2_surface.report["parameters"]["keep_on_surface"] is False
    assert fas2_surface.report["parameters"]["hetatm"] is True


def test_options_map_to_cli_flags(tmp_path, fas2_atoms):
    run_cli("surface", DATA / "fas2.pqr", "-o", tmp_path / "s.ply", "--spacing", "0.8",
            "--surface", "gaussian", "--blobbyness", "-0.7", "--coarsen", "0.2,0.3", "--rings", "3", "--beta", "1.5",
            "--blur", "fast", "--no-keep-on-surface", "--stats", tmp_path / "s.json")
    surf = molmesh.surface(fas2_atoms, spacing=0.8, surface="gaussian", blobbyness=-0.7, coarsen=[0.2, 0.3],
                           rings=3, beta=1.5, blur="fast", keep_on_surface=False)
    assert_same_mesh(surf, molmesh.read_surface(tmp_path / "s.ply"))
    assert surf.report["parameters"]["coarsen"] == [0.2, 0.3]
    assert surf.report["parameters"] == read_json(tmp_path / "s.json")["parameters"]


def test_ses_surface_is_the_clis_bit_for_bit(tmp_path):
    run_cli("surface", DATA / "1a1p.pqr", "--surface", "ses", "-o", tmp_path / "x.off")
    atoms = molmesh.read_atoms(DATA / "1a1p.pqr")
    surf = molmesh.surface(atoms, surface="ses")
    assert surf.report["parameters"]["surface"] == "ses"
    assert_same_mesh(surf, molmesh.read_surface(tmp_path / "x.off"))
    # keep_on_surface projects every processing move back onto the SES: other vertices.
    kept = molmesh.surface(atoms, surface="ses", keep_on_surface=True)
    assert kept.report["parameters"]["keep_on_surface"] is True
    assert kept.stats()["min_angle_deg"] != surf.stats()["min_angle_deg"]
    # Not the Gaussian surface of the same atoms.
    assert surf.vertices.shape != molmesh.surface(atoms, surface="gaussian").vertices.shape
    # The Gaussian's own options are refused for another surface, the default SES too.
    with pytest.raises(molmesh.OptionError, match="`blobbyness` applies only to the Gaussian"):
        molmesh.surface(atoms, blobbyness=-2.0)
    with pytest.raises(ValueError, match="surface='sphere': expected one of"):
        molmesh.surface(atoms, surface="sphere")
    with pytest.raises(molmesh.OptionError, match="`probe_radius`"):
        molmesh.surface(atoms, surface="sas", probe_radius=-1.0)
    with pytest.raises(ValueError, match="`isovalue`"):  # OptionError is a ValueError
        molmesh.surface(atoms, isovalue=-1.0)


def test_keep_spheres_as_file_or_array(tmp_path, fas2_atoms):
    spheres = tmp_path / "site.spheres"
    spheres.write_text("-13.3 3.0 35.9 6.0\n")
    run_cli("surface", DATA / "fas2.pqr", "-o", tmp_path / "k.ply", "--spacing", "0.8",
            "--keep-spheres", spheres)
    from_file = molmesh.surface(fas2_atoms, spacing=0.8, keep_spheres=spheres)
    from_array = molmesh.surface(fas2_atoms, spacing=0.8,
                                 keep_spheres=np.array([[-13.3, 3.0, 35.9, 6.0]]))
    assert_same_mesh(from_file, molmesh.read_surface(tmp_path / "k.ply"))
    assert_same_mesh(from_array, from_file)
    np.testing.assert_array_equal(molmesh.read_spheres(spheres), [[-13.3, 3.0, 35.9, 6.0]])


def test_volume_round_trip_and_contouring(tmp_path, fas2_atoms):
    surf = molmesh.surface(fas2_atoms, surface="gaussian", raw=True, spacing=1.0, keep_volume=True)
    volume = surf.report["volume"]
    assert volume.values.shape == tuple(surf.report["grid_dims"])
    # values[i, j, k] sits at origin + (i, j, k) * spacing; the field is > 1 inside atoms.
    assert volume.values.max() > 1.0 and volume.values.flags.f_contiguous
    again = molmesh.surface(volume, raw=True)
    assert_same_mesh(again, surf)
    volume.write(tmp_path / "v.dx")
    run_cli("surface", tmp_path / "v.dx", "-o", tmp_path / "v.ply", "--raw",
            "--stats", tmp_path / "v.json")
    from_file = molmesh.read_volume(tmp_path / "v.dx")
    assert from_file.shape == volume.shape
    contoured = molmesh.surface(from_file, raw=True)
    assert_same_mesh(contoured, molmesh.read_surface(tmp_path / "v.ply"))
    # A volume has no atom selection: neither front end records one (docs/cli.md).
    parameters = read_json(tmp_path / "v.json")["parameters"]
    assert contoured.report["parameters"] == parameters
    assert not {"radii", "hetatm", "waters"} & set(parameters)
    assert parameters["raw"] is True and parameters["isovalue"] == 1.0
    # A volume's surface is projected onto its level set only when asked (docs/processing.md),
    # and both front ends record what was done, not the Gaussian default for atoms.
    assert parameters["keep_on_surface"] is False
    built = molmesh.Volume(np.asarray(volume.values), volume.origin, volume.spacing)
    assert_same_mesh(molmesh.surface(built, raw=True), surf)


def test_arrays_are_read_only_views(fas2_surface):
    v = fas2_surface.vertices
    assert not v.flags.writeable
    with pytest.raises(ValueError):
        v[0, 0] = 1.0
    # A view of the C++ data: the same memory every time, alive while the view is.
    assert fas2_surface.vertices.__array_interface__["data"][0] == v.__array_interface__["data"][0]


def test_surface_from_arrays_and_writers(tmp_path, fas2_surface):
    copy = molmesh.Surface(fas2_surface.vertices, fas2_surface.faces.astype(np.int64))
    assert_same_mesh(copy, fas2_surface)
    for ext in ["off", "obj", "stl", "ply"]:
        copy.write(tmp_path / f"m.{ext}")
        back = molmesh.read_surface(tmp_path / f"m.{ext}")
        assert back.faces.shape == copy.faces.shape
    with pytest.raises(ValueError, match="refers to vertex"):
        molmesh.Surface(np.zeros((3, 3)), [[0, 1, 3]])
    with pytest.raises(TypeError, match="integer"):
        molmesh.Surface(np.zeros((3, 3)), [[0.0, 1.0, 2.0]])
    with pytest.raises(molmesh.OutputError) as info:
        copy.write(tmp_path / "no" / "such" / "dir" / "m.off")
    assert isinstance(info.value, OSError)


def test_meshio_reads_the_same_mesh(tmp_path, fas2_surface):
    meshio = pytest.importorskip("meshio")
    m = fas2_surface.to_meshio()
    meshio.write(tmp_path / "m.vtu", m)
    back = meshio.read(tmp_path / "m.vtu")
    np.testing.assert_array_equal(back.points, fas2_surface.vertices)
    np.testing.assert_array_equal(back.cells_dict["triangle"], fas2_surface.faces)
    fas2_surface.write(tmp_path / "w.ply")
    np.testing.assert_array_equal(meshio.read(tmp_path / "w.ply").points, fas2_surface.vertices)


def test_progress_is_reported_per_stage(fas2_atoms):
    calls = []
    molmesh.surface(fas2_atoms, spacing=1.0, progress=lambda stage, f: calls.append((stage, f)))
    stages = [s for s, _ in calls]
    for name in ["distance field", "marching cubes", "improve", "coarsen", "smooth"]:
        assert name in stages
    assert all(0.0 <= f <= 1.0 for _, f in calls)


class Stop(Exception):
    pass


def test_an_exception_in_the_callback_aborts_the_stage(fas2_atoms):
    def stop_in_marching_cubes(stage, fraction):
        if stage == "marching cubes":
            raise Stop(stage)

    with pytest.raises(Stop, match="marching cubes"):
        molmesh.surface(fas2_atoms, spacing=1.0, progress=stop_in_marching_cubes)
    # Nothing is left stuck: the next call works.
    assert molmesh.surface(fas2_atoms, spacing=1.0, raw=True).stats()["closed"]


def test_ctrl_c_interrupts_a_stage(fas2_atoms):
    def interrupt(stage, fraction):
        if stage == "improve":
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        molmesh.surface(fas2_atoms, spacing=1.0, progress=interrupt)


def test_warnings_filter_as_error_aborts(tmp_path):
    pqr = tmp_path / "zero.pqr"
    pqr.write_text("ATOM      1  N   ALA     1       0.000   0.000   0.000  0.0 1.5\n"
                   "ATOM      2  H   ALA     1       1.000   0.000   0.000  0.0 0.0\n")
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", molmesh.Warning)
        with pytest.raises(molmesh.Warning):
            molmesh.read_atoms(pqr)


def test_result_does_not_depend_on_the_thread_count(fas2_atoms):
    with molmesh.thread_limit(1):
        one = molmesh.surface(fas2_atoms, spacing=1.0)
    assert_same_mesh(one, molmesh.surface(fas2_atoms, spacing=1.0))


def test_library_errors_are_molmesh_errors(fas2_atoms):
    with pytest.raises(molmesh.Error, match="isovalue"):
        molmesh.surface(fas2_atoms, isovalue=1e9, spacing=1.0)
    with pytest.raises(TypeError, match="unexpected keyword"):
        molmesh.surface(fas2_atoms, spacings=1.0)
    with pytest.raises(ValueError, match="blur='slow'"):
        molmesh.surface(fas2_atoms, blur="slow")
    with pytest.raises(TypeError, match="spacing"):
        molmesh.surface(fas2_atoms, spacing="fine")
