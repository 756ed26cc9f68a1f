"""Keyword values outside the library's ranges (SurfacePipelineOptions::validate(),
ProcessingOptions::validate(), ImprovePipelineOptions::validate()) raise molmesh.Error naming
the Python keyword, before any work; the docstrings print those ranges."""
import math

import numpy as np
import pytest

import molmesh

NAN = math.nan
INF = math.inf


@pytest.fixture(scope="module")
def ion():
    return molmesh.Atoms(np.zeros((1, 3)), np.array([1.5]))


@pytest.fixture(scope="module")
def ion_surface(ion):
    return molmesh.surface(ion, raw=True)


@pytest.mark.parametrize("keyword, value", [
    ("spacing", NAN), ("spacing", 0.0), ("probe_radius", -1.0), ("blobbyness", 0.5),
    ("blobbyness", -INF), ("isovalue", NAN), ("isovalue", -1.0), ("min_cavity_volume", INF),
    ("rings", 0), ("rings", 11), ("alpha", NAN), ("beta", -1.0), ("sweeps", 101),
    ("feature_weight", INF), ("smooth_iterations", -1), ("cleanup_rounds", 1000),
    ("coarsen", [0.2, NAN]), ("coarsen", [-0.1]),
])
def test_surface_refuses_out_of_range_keywords_by_name(ion, keyword, value):
    with pytest.raises(molmesh.Error, match=f"`{keyword}` must be a finite number in"):
        molmesh.surface(ion, **{keyword: value})


def test_tetmesh_from_atoms_names_coarsen_too(ion):
    with pytest.raises(molmesh.Error, match="`coarsen`"):
        molmesh.tetmesh(ion, coarsen=[INF])


@pytest.mark.parametrize("keyword, value", [
    ("t0", [NAN]), ("t0", [0.1, -1.0]), ("merge_tolerance", -1.0), ("merge_tolerance", NAN),
    ("sweeps", 101), ("smooth_iterations", 101), ("rings", 0),
])
def test_improve_refuses_out_of_range_keywords_by_name(ion_surface, keyword, value):
    with pytest.raises(molmesh.Error, match=f"`{keyword}` must be a finite number in"):
        molmesh.improve(ion_surface, **{keyword: value})


def test_a_volumes_isovalue_may_be_negative(ion):
    """A potential map's level can be below zero; the atoms' range does not apply."""
    volume = molmesh.surface(ion, raw=True, keep_volume=True).report["volume"]
    shifted = molmesh.Volume(np.asfortranarray(volume.values) - 2.0, volume.origin, volume.spacing)
    surf = molmesh.surface(shifted, isovalue=-1.0, raw=True)
    assert surf.faces.shape[0] > 0
    with pytest.raises(molmesh.Error, match="`isovalue`"):
        molmesh.surface(shifted, isovalue=NAN, raw=True)


def test_docstrings_print_the_ranges():
    assert "spacing" in molmesh.surface.__doc__
    for text in ["(0, inf)", "[1, 10]", "[-1e+06, -1e-12]", "[0, 100]"]:
        assert text in molmesh.surface.__doc__, text
    assert "[0, inf)" in molmesh.improve.__doc__


def test_hierarchy_and_atom_keywords_say_what_the_cli_says():
    """One table each (hierarchy_option_specs.hpp, atom_option_specs.hpp): the sentences of
    `molmesh hierarchy --help` are the docstrings' (the flag and keyword spellings aside)."""
    from conftest import run_cli
    cli = " ".join(run_cli("hierarchy", "--help").stdout.split())
    for sentence in ["Coarsening thresholds T0 (Eq. 6), one level each, finest first, non-decreasing",
                     "so coarse levels coarsen the far field too, not only the surface",
                     "Renumber every volume mesh by reverse Cuthill-McKee"]:
        assert sentence in cli and sentence in molmesh.hierarchy.__doc__, sentence
    for sentence in ["for PQR input it replaces the file's radii wherever it has an entry",
                     "Include HETATM records (ligands, ions)",
                     "Include water molecules (HOH, WAT, ...), which are dropped by default"]:
        assert sentence in cli and sentence in molmesh.read_atoms.__doc__, sentence
