#!/usr/bin/env python3
"""Slice plot of the 'concentration' field of level 0 of a molmesh hierarchy:
vertices within 1.5 Å of the plane through the active-site centre (mean of the
active-site vertices) perpendicular to y, coloured by concentration (units of c_bulk)."""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

h5, png = sys.argv[1], sys.argv[2]
with h5py.File(h5, "r") as f:
    vol = f["levels/0/volume"]
    pts = vol["points"][:]
    conc = vol["fields/concentration"][:]
    faces = vol["boundary_faces"][:]
    marks = vol["boundary_face_markers"][:]
site = pts[np.unique(faces[marks == 3])]
centre = site.mean(axis=0) if len(site) else pts.mean(axis=0)
sel = np.abs(pts[:, 1] - centre[1]) < 1.5
near = np.linalg.norm(pts[:, [0, 2]] - centre[[0, 2]], axis=1) < 60
sel &= near
fig, ax = plt.subplots(figsize=(7, 6))
sc = ax.scatter(pts[sel, 0], pts[sel, 2], c=conc[sel], s=4, cmap="jet", vmin=0, vmax=1)
fig.colorbar(sc, label="c / c_bulk")
ax.set_xlabel("x (Å)")
ax.set_ylabel("z (Å)")
ax.set_aspect("equal")
ax.set_title("Steady-state concentration, slice y = %.1f Å" % centre[1])
fig.savefig(png, dpi=120)
