"""`cmake --install` into a temporary prefix gives a working package: from another
directory, with only the installed site dir on PYTHONPATH, `import molmesh` loads the
installed copy (extension, .py files, stubs) and runs."""
import hashlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

import molmesh
from conftest import DATA, program_env

SCRIPT = """
import hashlib, sys
import molmesh
atoms = molmesh.read_atoms(sys.argv[1])
print(molmesh.__file__)
print(molmesh.__version__)
print(len(atoms), hashlib.sha256(atoms.positions.tobytes()).hexdigest())
"""


def test_installed_package_imports_from_anywhere(tmp_path):
    site_dir = os.environ["MOLMESH_PYTHON_INSTALL_DIR"]
    if os.path.isabs(site_dir):
        pytest.skip("MOLMESH_PYTHON_INSTALL_DIR is absolute: an install would leave the prefix")
    prefix = tmp_path / "prefix"
    install = [os.environ["MOLMESH_CMAKE"], "--install", os.environ["MOLMESH_BUILD_DIR"],
               "--prefix", str(prefix)]
    proc = subprocess.run(install, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    site = prefix / site_dir
    for name in ["__init__.py", "_core.pyi", "py.typed"]:
        assert (site / "molmesh" / name).exists(), name
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    proc = subprocess.run([sys.executable, "-c", SCRIPT, str(DATA / "fas2.pqr")], cwd=elsewhere,
                          env=env, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    where, version, atoms = proc.stdout.split("\n")[:3]
    assert Path(where).resolve() == (site / "molmesh" / "__init__.py").resolve()
    cli = subprocess.run([str(prefix / "bin" / "molmesh"), "--version"], capture_output=True,
                         text=True, check=True, env=program_env())
    assert version == molmesh.__version__ and cli.stdout.split() == ["molmesh", version]
    here = molmesh.read_atoms(DATA / "fas2.pqr")
    assert atoms == f"{len(here)} {hashlib.sha256(here.positions.tobytes()).hexdigest()}"
