"""The type stubs shipped with the package list every keyword each function accepts."""
import ast
from pathlib import Path

import pytest

import molmesh


def stub_functions():
    tree = ast.parse((Path(molmesh.__file__).parent / "_core.pyi").read_text())
    return {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}


@pytest.mark.parametrize("name", ["read_atoms", "surface", "improve", "tetmesh", "hierarchy",
                                  "solve_smoluchowski", "solve_poisson"])
def test_every_keyword_is_in_the_stub(name):
    node = stub_functions()[name]
    listed = {a.arg for a in node.args.kwonlyargs}
    assert set(molmesh.defaults(name)) <= listed, set(molmesh.defaults(name)) - listed


def test_every_public_name_has_a_stub():
    tree = ast.parse((Path(molmesh.__file__).parent / "_core.pyi").read_text())
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {n for n in dir(molmesh._core) if not n.startswith("_")}
    assert public <= stubbed, public - stubbed
    assert (Path(molmesh.__file__).parent / "py.typed").exists()
