#!/usr/bin/env python3
"""Writes the seed corpora in tests/fuzz/corpus/READER from the repo's real molecules
(tests/data) and small hand-made meshes and grids in every encoding the readers accept.
Re-run after changing a reader's format; the seeds are committed (small by design).
The hierarchy seed (corpus/hierarchy/two_atoms_interior.h5, 57 KB) was written by the CLI:
  printf 'ATOM 1 C ALA 1 0 0 0 0 1.6\nATOM 2 O ALA 1 1.2 0 0 0 1.5\n' > two.pqr
  molmesh hierarchy two.pqr -o h.h5 --t0 0.1 --domain interior --spacing 0.8 \
      --outer-sphere-subdivisions 0
"""
import os
import struct
import sys

here = os.path.dirname(os.path.abspath(__file__))
data = os.path.join(here, "..", "data")
corpus = os.path.join(here, "corpus")


def put(reader, name, content):
    folder = os.path.join(corpus, reader)
    os.makedirs(folder, exist_ok=True)
    if isinstance(content, str):
        content = content.encode()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(content)


def head_records(path, n, keep=lambda line: True):
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith(("ATOM", "HETATM")):
                if len([l for l in out if l.startswith(("ATOM", "HETATM"))]) >= n:
                    break
            if keep(line):
                out.append(line)
    return "".join(out)


# Molecules: the first residues of 1a1p in each format, plus layouts the readers tolerate.
put("pqr", "1a1p_head.pqr", head_records(os.path.join(data, "1a1p.pqr"), 12))
put("pqr", "variants.pqr",
    "REMARK glued, chain, HETATM, element and later model\n"
    "ATOM      1  N   ALA A   1     -12.345-6.789   1.000 -0.30 1.82\n"
    "HETATM12345  O   HOH   100      1.0   2.0   3.0  0.0 1.5 O\n"
    "ATOM 3 CA GLY A1000 1e-1 +2 -3.5 0 0\n"
    "ENDMDL\nATOM 4 C ALA 1 0 0 0 0 1\n")
put("pdb", "1a1p_head.pdb", head_records(os.path.join(data, "1a1p.pdb"), 12))
put("pdb", "layouts.pdb",
    "HEADER    TEST\n"
    "ATOM      1  CA AALA A   1       1.000   0.000   0.000  0.60  0.00           C  \n"
    "ATOM      2  CA BALA A   1       1.500   0.000   0.000  0.40  0.00           C  \n"
    "HETATM    3 FE   HEM B 200      10.000  10.000  10.000  1.00  0.00          FE  \n"
    "ATOM\t4\tC\tUNK\tA\t1\t0.5000\t-1.2390\t0.0110\t1.00\t0.00\tC\n"
    "ATOM      5  ION   ION     1      -3.000   0.000   0.000  1.00 2.00\n"
    "MODEL        2\nATOM      6  N   ALA A   1       0.000   0.000   0.000  1.00  0.00           N\n"
    "ENDMDL\nEND\n")
cif = open(os.path.join(data, "1a1p.cif")).read().splitlines(keepends=True)
rows = [i for i, l in enumerate(cif) if l[:1].isdigit() and " ILE " in l]
start = next(i for i, l in enumerate(cif) if l.startswith("loop_") and cif[i + 1].startswith("_atom_site."))
put("mmcif", "1a1p_head.cif", "data_1a1p\n" + "".join(cif[start:rows[0]]) + "".join(cif[rows[0]:rows[0] + 10]))

# One octahedron in every surface format.
P = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
T = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
pts = "".join("%g %g %g\n" % p for p in P)
put("off", "octahedron.off", "OFF\n# comment\n%d %d 0\n%s%s" % (
    len(P), len(T), pts, "".join("3 %d %d %d\n" % t for t in T)))
put("off", "quad.off", "OFF 4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
put("obj", "octahedron.obj", "# o\n" + "".join("v %g %g %g\n" % p for p in P) +
    "".join("f %d/1 %d//2 %d\n" % (a + 1, b + 1, c + 1) for a, b, c in T[:4]) +
    "".join("f -6 -4 -2\n" for _ in range(1)) + "vn 0 0 1\n")


def ply_header(fmt, markers):
    h = "ply\nformat %s 1.0\ncomment seed\nelement vertex %d\n" % (fmt, len(P))
    h += "property double x\nproperty double y\nproperty double z\n"
    if markers:
        h += "property int marker\n"
    h += "element face %d\nproperty list uchar int vertex_indices\n" % len(T)
    if markers:
        h += "property int marker\n"
    return h + "end_header\n"


put("ply", "ascii.ply", ply_header("ascii", True) + "".join("%g %g %g %d\n" % (p + (i,)) for i, p in enumerate(P)) +
    "".join("3 %d %d %d 1\n" % t for t in T))
for fmt, order in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
    body = b"".join(struct.pack(order + "dddi", *(p + (i,))) for i, p in enumerate(P))
    body += b"".join(struct.pack(order + "Biiii", 3, *t, 2) for t in T)
    put("ply", fmt + ".ply", ply_header(fmt, True).encode() + body)
put("ply", "float_uint.ply",
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uint8 uint32 vertex_index\nend_header\n".encode() +
    struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<BIII", 3, 0, 1, 2))

facets = "".join("facet normal 0 0 1\n outer loop\n" + "".join("  vertex %g %g %g\n" % P[v] for v in t) +
                 " endloop\nendfacet\n" for t in T)
put("stl", "ascii.stl", "solid seed\n" + facets + "endsolid seed\n")
binary = b"seed".ljust(80, b" ") + struct.pack("<I", len(T))
for t in T:
    binary += struct.pack("<3f", 0, 0, 1) + b"".join(struct.pack("<3f", *P[v]) for v in t) + b"\0\0"
put("stl", "binary.stl", binary)

put("msms", "octahedron.msms",
    "# MSMS vertices\n#vertex #sphere density probe_r\n%d 0 0.00 0.00\n" % len(P) +
    "".join("%12.6f %12.6f %12.6f 0 0 1 0 0 2\n" % p for p in P) + "\n@face\n" +
    "# MSMS faces\n#faces #sphere density probe_r\n%d 0 0.00 0.00\n" % len(T) +
    "".join("%d %d %d 1 0\n" % (a + 1, b + 1, c + 1) for a, b, c in T))

# Grids: 3 x 2 x 2 values in DX (APBS layout) and MRC (both byte orders, modes 0, 1, 2, 6).
vals = [0.5 * i - 2.25 for i in range(12)]
put("dx", "apbs.dx",
    "# APBS-like\nobject 1 class gridpositions counts 3 2 2\norigin -1.5 0 2.25\n"
    "delta 0.5 0 0\ndelta 0 0.75 0\ndelta 0 0 1.25\nobject 2 class gridconnections counts 3 2 2\n"
    "object 3 class array type double rank 0 items 12 data follows\n" +
    "".join("%g %g %g\n" % tuple(vals[i:i + 3]) for i in range(0, 12, 3)) +
    'attribute "dep" string "positions"\nobject "x" class field\ncomponent "data" value 3\n')


def mrc(order, mode, nsymbt=0, origin=(0.0, 0.0, 0.0)):
    w = [0] * 256
    h = bytearray(1024)

    def i32(word, v):
        struct.pack_into(order + "i", h, 4 * (word - 1), v)

    def f32(word, v):
        struct.pack_into(order + "f", h, 4 * (word - 1), v)
    for k, n in enumerate((3, 2, 2)):
        i32(1 + k, n)
        i32(8 + k, n)
        f32(11 + k, 1.5 * n)
        f32(14 + k, 90.0)
        i32(17 + k, k + 1)
        f32(50 + k, origin[k])
    i32(4, mode)
    i32(24, nsymbt)
    h[208:212] = b"MAP "
    h[212:214] = b"\x44\x44" if order == "<" else b"\x11\x11"
    fmt = {0: "b", 1: "h", 2: "f", 6: "H"}[mode]
    data = b"".join(struct.pack(order + fmt, int(v) + 3 if mode != 2 else v) for v in vals)
    return bytes(h) + b"\0" * nsymbt + data


put("mrc", "le_mode2.mrc", mrc("<", 2, origin=(1.0, -2.0, 0.5)))
put("mrc", "be_mode1.mrc", mrc(">", 1))
put("mrc", "le_mode0_ext.mrc", mrc("<", 0, nsymbt=8))
put("mrc", "le_mode6.mrc", mrc("<", 6))

put("radius_table", "table.radii", "# comment\nC 1.70\nN 1.55  # nitrogen\nHEM FE 1.80\n* 1.5\n")
put("sphere_list", "spheres.txt", "# x y z r\n0 0 0 1.5\n1.5, 0, 0, 1.2\n-1e-1 +2 3 0\n")

put("mcsf", "one_tet.m",
    "mcsf_begin=1;\n\n      dim=3;\n    dimii=3;\n vertices=5;\nsimplices=2;\n\nvert=[\n"
    "% comment\n0 0 0 0 0\n1 0 1 0 0\n2 0 0 1 0\n3 0 0 0 1\n4 0 1 1 1\n];\n\n"
    "simp=[\n0 0 1 1 1 1 0 0 1 2 3\n1 0 2 0 2 3 1 1 2 3 4\n];\n\nmcsf_end=1;\n")
