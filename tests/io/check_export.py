"""Independent readers for `molmesh export` output: meshio reads every exported mesh,
scipy reads the Matrix Market prolongations, numpy parses the PETSc binary ones by the
format PETSc documents (MatView/MatLoad: big-endian int32 header, row counts, columns,
float64 values), and all of them must equal what the HDF5 file holds (h5py).

usage: check_export.py HIER.h5 PREFIX"""
import sys

import h5py
import meshio
import numpy as np
import scipy.io
import scipy.sparse

h5_path, prefix = sys.argv[1], sys.argv[2]


def as_set(cells):
    """Cells as sorted rows in sorted order: Gmsh files group them by physical group."""
    rows = np.sort(cells, axis=1)
    return rows[np.lexsort(rows.T[::-1])]


def read_petsc_binary(path):
    raw = open(path, "rb").read()
    header = np.frombuffer(raw, dtype=">i4", count=4)
    assert header[0] == 1211216, f"{path}: classid {header[0]}"
    rows, cols, nnz = (int(v) for v in header[1:])
    offset = 16
    per_row = np.frombuffer(raw, dtype=">i4", count=rows, offset=offset)
    offset += 4 * rows
    columns = np.frombuffer(raw, dtype=">i4", count=nnz, offset=offset)
    offset += 4 * nnz
    values = np.frombuffer(raw, dtype=">f8", count=nnz, offset=offset)
    offset += 8 * nnz
    assert offset == len(raw), f"{path}: {len(raw) - offset} trailing bytes"
    indptr = np.concatenate([[0], np.cumsum(per_row)])
    return scipy.sparse.csr_matrix((values, columns, indptr), shape=(rows, cols))


checked = 0
with h5py.File(h5_path, "r") as h5:
    levels = int(h5.attrs["num_levels"])
    for level in range(levels):
        volume = h5[f"levels/{level}/volume"]
        points = volume["points"][()]
        tets = volume["tetrahedra"][()]
        regions = volume["cell_markers"][()]
        base = f"{prefix}_L{level}"
        for suffix in ("_volume.vtu", "_volume.msh"):
            m = meshio.read(base + suffix)
            assert np.allclose(m.points, points), base + suffix
            got = np.concatenate([c.data for c in m.cells if c.type == "tetra"])
            if suffix.endswith(".vtu"):
                assert np.array_equal(got, tets), base + suffix
            else:
                assert np.array_equal(as_set(got), as_set(tets)), base + suffix
            checked += 1
        vtu = meshio.read(base + "_volume.vtu")
        tet_blocks = [i for i, c in enumerate(vtu.cells) if c.type == "tetra"]
        got_regions = np.concatenate([vtu.cell_data["region"][i] for i in tet_blocks])
        assert np.array_equal(got_regions, regions), "regions"
        assert np.array_equal(vtu.point_data["marker"], volume["vertex_markers"][()])
        surface = h5[f"levels/{level}/surface"]
        for suffix in ("_surface.vtu", "_surface.off"):
            m = meshio.read(base + suffix)
            assert np.allclose(m.points, surface["points"][()]), base + suffix
            tris = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
            assert np.array_equal(tris, surface["triangles"][()]), base + suffix
            checked += 1
    for level in range(levels - 1):
        for kind in ("volume", "surface"):
            g = h5[f"transfer/{level + 1}_to_{level}/{kind}"]
            p = scipy.sparse.csr_matrix(
                (g["data"][()], g["indices"][()], g["indptr"][()]), shape=tuple(g.attrs["shape"])
            )
            base = f"{prefix}_P{level + 1}_to_{level}_{kind}"
            mtx = scipy.sparse.csr_matrix(scipy.io.mmread(base + ".mtx"))
            petsc = read_petsc_binary(base + ".petsc")
            for name, got in (("mtx", mtx), ("petsc", petsc)):
                assert got.shape == p.shape, (name, got.shape, p.shape)
                assert abs(got - p).max() == 0.0, f"{base}.{name} differs from the HDF5"
                checked += 1
print(f"checked {checked} files of {levels} levels")
