"""molmesh: molecules to adaptive surface and tetrahedral meshes (the GAMer method).

Every stage of the ``molmesh`` command line as a function over plain objects whose arrays
are numpy views (read-only, no copy) with documented dtypes and shapes::

    import molmesh
    atoms = molmesh.read_atoms("fas2.pqr")
    surf = molmesh.surface(atoms, progress=lambda stage, f: print(stage, f))
    tets = molmesh.tetmesh(surf, atoms, domain="exterior")
    h = molmesh.hierarchy(atoms, t0=[0.1, 0.3, 0.5], domain="exterior")
    result = molmesh.solve_smoluchowski(h)   # result.rate_constant, M^-1 s^-1

Keyword defaults are the library's (and the CLI's): ``molmesh.defaults("surface")``.
docs/python.md in the source tree is the guide.
"""

from ._core import (
    Atoms,
    Error,
    Hierarchy,
    HierarchyLevel,
    SolveResult,
    InputError,
    OptionError,
    OutputError,
    Surface,
    TetMesh,
    Volume,
    Warning,
    __version__,
    defaults,
    hierarchy,
    improve,
    point_field_names,
    read_atoms,
    read_hierarchy,
    read_point_field,
    read_spheres,
    read_surface,
    read_tetmesh,
    read_volume,
    solve_poisson,
    solve_smoluchowski,
    surface,
    tetmesh,
    thread_limit,
    write_point_field,
    write_point_fields,
)
from . import _core
from ._meshio import surface_to_meshio as _surface_to_meshio
from ._meshio import tetmesh_to_meshio as _tetmesh_to_meshio

Surface.to_meshio = _surface_to_meshio
TetMesh.to_meshio = _tetmesh_to_meshio

__all__ = [name for name in dir() if not name.startswith("_")]
