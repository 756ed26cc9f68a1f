"""Shared fixtures of the Python module tests: the data files, the CLI (run on the same
input for bit-for-bit comparisons) and results that several tests reuse."""
import json
import os
import subprocess
from pathlib import Path

import pytest

import molmesh

DATA = Path(os.environ.get("MOLMESH_TEST_DATA", Path(__file__).resolve().parents[1] / "data"))
CLI = os.environ.get("MOLMESH_CLI", "molmesh")


def program_env():
    """The environment for running one of molmesh's programs. In the sanitizer build the
    tests preload the shared AddressSanitizer runtime into Python (tests/python/CMakeLists.txt);
    the programs carry their own static copy and refuse a second one, so it is taken out."""
    preload = os.environ.get("MOLMESH_SANITIZER_PRELOAD")
    if not preload:
        return None
    return {k: v for k, v in os.environ.items() if not (k == "LD_PRELOAD" and v == preload)}


def run_cli(*args, expect=0):
    """Runs `molmesh -q ARGS`; returns the completed process (asserts the exit code)."""
    proc = subprocess.run([CLI, "-q", *map(str, args)], capture_output=True, text=True,
                          env=program_env())
    assert proc.returncode == expect, proc.stderr
    return proc


def read_json(path):
    with open(path) as f:
        return json.load(f)


@pytest.fixture(scope="session")
def data():
    return DATA


@pytest.fixture(scope="session")
def fas2_atoms():
    return molmesh.read_atoms(DATA / "fas2.pqr")


@pytest.fixture(scope="session")
def fas2_cli_surface(tmp_path_factory):
    """`molmesh surface fas2.pqr` with defaults: (surface read back, --stats document)."""
    out = tmp_path_factory.mktemp("cli_surface")
    run_cli("surface", DATA / "fas2.pqr", "-o", out / "fas2.ply", "--stats", out / "fas2.json")
    return molmesh.read_surface(out / "fas2.ply"), read_json(out / "fas2.json")


@pytest.fixture(scope="session")
def fas2_surface(fas2_atoms):
    """molmesh.surface(fas2) with defaults."""
    return molmesh.surface(fas2_atoms)
