"""molmesh.solve_smoluchowski and molmesh.solve_poisson against `molmesh solve` on the
same hierarchy file: the same rate constant and solvation energy, bit for bit."""
import numpy as np
import pytest

import molmesh
from conftest import DATA, read_json, run_cli

# What `molmesh solve --json` says of the command line rather than of the solve.
COMMON_CLI_ONLY = {"problem", "engine", "hierarchy", "level", "vertices", "tetrahedra",
                   "coarse_operators", "total_time_s"}
SMOLUCHOWSKI_CLI_ONLY = COMMON_CLI_ONLY | {"absorbing", "diffusion_cm2_per_s", "potential",
                                           "charge"}
POISSON_CLI_ONLY = COMMON_CLI_ONLY | {"pqr", "pdie", "sdie"}


@pytest.fixture(scope="module")
def cli_hierarchy(tmp_path_factory):
    out = tmp_path_factory.mktemp("solve")
    run_cli("hierarchy", DATA / "1a1p.pqr", "-o", out / "h.h5", "--t0", "0.1,0.3,0.5",
            "--domain", "full")
    return out / "h.h5"


@pytest.fixture(scope="module")
def hierarchy(cli_hierarchy):
    return molmesh.read_hierarchy(cli_hierarchy)


@pytest.mark.parametrize("level", [0, 1])
def test_rate_is_the_clis(tmp_path, cli_hierarchy, hierarchy, level):
    run_cli("solve", "smoluchowski", cli_hierarchy, "--level", level, "--json",
            tmp_path / "s.json", "--no-fields")
    cli = read_json(tmp_path / "s.json")
    result = molmesh.solve_smoluchowski(hierarchy, level=level)
    assert result.rate_constant == cli["rate_constant_M-1s-1"]
    assert result.rate_constant_A3_per_s == cli["rate_constant_A3_per_s"]
    assert result.iterations == cli["iterations"] and result.converged
    assert result.report["residual_history"] == cli["residual_history"]
    # The solve's keys are one writer's (solvers/physics/result_json.hpp); the CLI adds its
    # options and the problem's name.
    assert set(result.report) - {"parameters"} == set(cli) - SMOLUCHOWSKI_CLI_ONLY
    c = result.fields["concentration"]
    assert c.shape == (len(hierarchy.levels[level].volume.vertices),)
    assert 0.0 <= c.min() and c.max() <= 1.0 + 1e-9


def test_solver_options_and_fields_match_the_cli(tmp_path, cli_hierarchy, hierarchy):
    run_cli("solve", "smoluchowski", cli_hierarchy, "--json", tmp_path / "s.json",
            "--preconditioner", "ic", "--tolerance", "1e-6")
    cli = read_json(tmp_path / "s.json")
    result = molmesh.solve_smoluchowski(hierarchy, preconditioner="ic", tolerance=1e-6)
    assert result.rate_constant == cli["rate_constant_M-1s-1"]
    stored = molmesh.read_point_field(cli_hierarchy, 0, "concentration")
    assert np.array_equal(stored, result.fields["concentration"])


def test_potential_and_charge_are_the_clis(tmp_path, cli_hierarchy, hierarchy):
    """A potential steers the rate through beta W = charge * phi as in the CLI; the charge
    default is the CLI's (one struct, solvers::LigandPotential)."""
    atoms = molmesh.read_atoms(DATA / "1a1p.pqr")
    phi = molmesh.surface(atoms, raw=True, spacing=1.0, keep_volume=True).report["volume"]
    phi.write(tmp_path / "phi.dx")
    run_cli("solve", "smoluchowski", cli_hierarchy, "--level", 1, "--potential",
            tmp_path / "phi.dx", "--json", tmp_path / "default.json", "--no-fields")
    run_cli("solve", "smoluchowski", cli_hierarchy, "--level", 1, "--potential",
            tmp_path / "phi.dx", "--charge", -2, "--json", tmp_path / "minus2.json",
            "--no-fields")
    default, minus2 = read_json(tmp_path / "default.json"), read_json(tmp_path / "minus2.json")
    assert molmesh.defaults("solve_smoluchowski")["charge"] == default["charge"]
    result = molmesh.solve_smoluchowski(hierarchy, level=1, potential=phi)
    assert result.report["parameters"]["charge"] == default["charge"]
    assert result.rate_constant == default["rate_constant_M-1s-1"]
    steered = molmesh.solve_smoluchowski(hierarchy, level=1, potential=tmp_path / "phi.dx",
                                         charge=-2.0)
    assert steered.rate_constant == minus2["rate_constant_M-1s-1"]
    assert steered.rate_constant != result.rate_constant
    np.testing.assert_allclose(steered.fields["beta_W"], -2.0 * result.fields["beta_W"])


def test_solvation_energy_is_the_clis(tmp_path, cli_hierarchy, hierarchy):
    run_cli("solve", "poisson", cli_hierarchy, "--pqr", DATA / "1a1p.pqr", "--json",
            tmp_path / "p.json", "--no-fields")
    cli = read_json(tmp_path / "p.json")
    result = molmesh.solve_poisson(hierarchy, molmesh.read_atoms(DATA / "1a1p.pqr"))
    assert result.solvation_energy == cli["solvation_energy_kJ_per_mol"]
    assert result.solvation_energy < 0
    assert result.report["iterations"] == cli["iterations"]
    assert set(result.report) - {"parameters"} == set(cli) - POISSON_CLI_ONLY
    assert set(result.report["reference_solve"]) == set(cli["reference_solve"])


def test_progress_can_abort_a_solve(hierarchy):
    class Stop(Exception):
        pass

    def stop(stage, fraction):
        if stage.startswith("smoluchowski: solve"):
            raise Stop()

    with pytest.raises(Stop):
        molmesh.solve_smoluchowski(hierarchy, progress=stop)


def test_bad_level_is_an_error(hierarchy):
    # The library's option name, which is the keyword too (the CLI says --level 7).
    with pytest.raises(molmesh.Error, match="^`level` 7: the hierarchy has 3 level"):
        molmesh.solve_smoluchowski(hierarchy, level=7)
    with pytest.raises(molmesh.Error, match="^`levels` must not be negative"):
        molmesh.solve_smoluchowski(hierarchy, levels=-1)
