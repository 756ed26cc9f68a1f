#!/usr/bin/python3
"""Independent reader for molmesh hierarchy files (used by the tests).

Reads the HDF5 file with h5py + scipy only, and every level's XDMF sidecar with meshio,
and checks the documented layout and invariants. Prints one line per problem and exits 1
if there was any; prints "OK <summary>" and exits 0 otherwise.

usage: check_hierarchy.py FILE.h5 [--field LEVEL NAME]
"""
import os
import sys

import h5py
import meshio
import numpy as np
import scipy.sparse

problems = []


def need(condition, message):
    if not condition:
        problems.append(message)
    return condition


def main():
    path = sys.argv[1]
    field = None
    if len(sys.argv) >= 5 and sys.argv[2] == "--field":
        field = (int(sys.argv[3]), sys.argv[4])
    folder = os.path.dirname(os.path.abspath(path))
    stem = os.path.splitext(os.path.basename(path))[0]
    with h5py.File(path, "r") as f:
        attrs = f.attrs
        need(attrs["format"] == "molmesh-hierarchy", "format attribute")
        need(int(attrs["format_version"]) == 1, "format_version")
        need(attrs["length_unit"] == "angstrom", "length_unit")
        n = int(attrs["num_levels"])
        need(len(attrs["t0"]) == n, "t0 has one value per level")
        need(len(attrs["input_sha256"]) == 64, "input_sha256 is 64 hex digits")
        need(any(k.startswith("param.") for k in attrs.keys()), "meshing parameters stored")
        sizes = []
        for level in range(n):
            g = f[f"levels/{level}"]
            v = g["volume"]
            pts = v["points"][...]
            tets = v["tetrahedra"][...]
            need(pts.shape[1] == 3 and tets.shape[1] == 4, f"level {level} shapes")
            need(v["points"].compression == "gzip" and v["points"].chunks is not None,
                 f"level {level} points chunked+deflate")
            need(tets.min() >= 0 and tets.max() < len(pts), f"level {level} tet indices")
            a, b, c, d = (pts[tets[:, k]] for k in range(4))
            det = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a)
            need((det > 0).all(), f"level {level}: {(det <= 0).sum()} tets not positively oriented")
            need(len(v["cell_markers"]) == len(tets), f"level {level} cell_markers")
            need(len(v["vertex_markers"]) == len(pts), f"level {level} vertex_markers")
            need(len(v["boundary_faces"]) == len(v["boundary_face_markers"]),
                 f"level {level} boundary faces/markers")
            perm = v["permutation"][...]
            need(len(perm) == 0 or np.array_equal(np.sort(perm), np.arange(len(pts))),
                 f"level {level} permutation")
            s = g["surface"]
            spts = s["points"][...]
            tris = s["triangles"][...]
            need(tris.max() < len(spts), f"level {level} triangle indices")
            prov = s["provenance"][...]
            if level > 0:
                need(len(prov) == len(spts), f"level {level} provenance length")
                need(prov.max() < sizes[-1][1], f"level {level} provenance range")
            sizes.append((len(pts), len(spts)))
            for kind, count in (("volume", len(pts)), ("surface", len(spts))):
                x = os.path.join(folder, f"{stem}_L{level}_{kind}.xdmf")
                m = meshio.read(x)
                need(len(m.points) == count, f"meshio {kind} level {level} points")
                need(np.allclose(m.points, pts if kind == "volume" else spts),
                     f"meshio {kind} level {level} coordinates")
                ncells = sum(len(block.data) for block in m.cells)
                need(ncells == (len(tets) if kind == "volume" else len(tris)),
                     f"meshio {kind} level {level} cells")
                if kind == "volume":
                    need("cell_markers" in m.cell_data, f"meshio level {level} cell_markers")
                    if field and field[0] == level:
                        need(field[1] in m.point_data, f"meshio sees field {field[1]}")
                        need(np.allclose(m.point_data[field[1]],
                                         v["fields"][field[1]][...]), "field values")
        need(os.path.exists(os.path.join(folder, f"{stem}.xdmf")), "collection xdmf")
        for fine in range(n - 1):
            g = f[f"transfer/{fine + 1}_to_{fine}"]
            need("transpose" in g.attrs["restriction"], "restriction attribute")
            for kind, k in (("volume", 0), ("surface", 1)):
                t = g[kind]
                p = scipy.sparse.csr_matrix(
                    (t["data"][...], t["indices"][...], t["indptr"][...]),
                    shape=tuple(t.attrs["shape"]))
                need(p.shape == (sizes[fine][k], sizes[fine + 1][k]), f"{kind} P shape")
                rows = np.asarray(p.sum(axis=1)).ravel()
                need(np.abs(rows - 1).max() < 1e-12, f"{kind} P rows sum to 1")
                cols = np.diff(p.tocsc().indptr)
                need((cols > 0).all(), f"{kind} P has {(cols == 0).sum()} empty columns")
    for p in problems:
        print("PROBLEM:", p)
    if problems:
        return 1
    print("OK levels", n, "sizes", sizes)
    return 0


if __name__ == "__main__":
    sys.exit(main())
