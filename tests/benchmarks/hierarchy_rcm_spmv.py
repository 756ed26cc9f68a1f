#!/usr/bin/python3
"""Does the RCM renumbering stored in a molmesh hierarchy pay off for sparse products?

Assembles the P1 stiffness matrix (+ lumped mass) of each level in the file's (RCM) order
and in TetGen's original order (undoing `permutation`), then times y = K x (CSR, scipy)
and 50 unpreconditioned CG iterations, best of several repeats.

usage: hierarchy_rcm_spmv.py FILE.h5
"""
import sys
import time

import h5py
import numpy as np
import scipy.sparse
import scipy.sparse.linalg


def stiffness(points, tets):
    e = points[tets[:, 1:]] - points[tets[:, :1]]  # (K, 3, 3), rows = edges
    vol = np.linalg.det(e) / 6.0
    inv = np.linalg.inv(e)  # columns: gradients of barycentrics 1..3
    g = np.concatenate([-inv.sum(axis=2, keepdims=True), inv], axis=2)  # (K, 3, 4)
    local = vol[:, None, None] * np.einsum("kdi,kdj->kij", g, g)
    local[:, range(4), range(4)] += (vol / 4.0)[:, None]
    rows = np.repeat(tets, 4, axis=1).ravel()
    cols = np.tile(tets, (1, 4)).ravel()
    n = len(points)
    return scipy.sparse.csr_matrix((local.ravel(), (rows, cols)), shape=(n, n))


def best(fn, repeats):
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times)


with h5py.File(sys.argv[1], "r") as f:
    print("level  vertices  order    half-bandwidth  SpMV (ms)  CG-50 (ms)")
    for level in range(int(f.attrs["num_levels"])):
        v = f[f"levels/{level}/volume"]
        pts, tets, perm = v["points"][...], v["tetrahedra"][...], v["permutation"][...]
        orders = {"rcm": (pts, tets)}
        if len(perm):
            # Original index of new vertex i is perm[i].
            orig_pts = np.empty_like(pts)
            orig_pts[perm] = pts
            orders["tetgen"] = (orig_pts, perm[tets])
        for name, (p, t) in sorted(orders.items(), reverse=True):
            k = stiffness(p, t)
            x = np.ones(k.shape[0])
            spmv = best(lambda: [k @ x for _ in range(20)], 5) / 20
            cg = best(lambda: scipy.sparse.linalg.cg(k, x, maxiter=50, atol=0.0, tol=1e-30), 3)
            bw = int((t.max(1) - t.min(1)).max())
            print(f"{level:5d}  {len(p):8d}  {name:7s}  {bw:14d}  {spmv * 1e3:9.3f}  {cg * 1e3:10.2f}")
