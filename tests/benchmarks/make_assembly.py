#!/usr/bin/env python3
"""Write a large PQR assembly made of rotated, translated copies of one molecule.

The benchmarks of docs/benchmarks.md use it to get a 33k-atom (4 copies) and a ~1M-atom
(120 copies) input from tests/data/mache.pqr, standing in for virus capsids and other
assemblies. Deterministic: the same arguments always give the same file.

  make_assembly.py tests/data/mache.pqr 120 mache120.pqr

Copies sit on a cubic lattice whose spacing is the diameter of the molecule's bounding
sphere (about its centroid) times --spacing-factor (default 1.0: bounding spheres touch, so
copies do not overlap but their surfaces come close, as in a packed assembly); each copy is
turned by its own random rotation (seeded).
"""
import argparse
import math
import random


def read_pqr(path):
    atoms = []
    with open(path) as f:
        for line in f:
            if not line.startswith(("ATOM", "HETATM")):
                continue
            fields = line.split()
            # record serial name resname resseq x y z q r (no chain id in these files)
            name, resname, resseq = fields[2], fields[3], fields[4]
            x, y, z, q, r = (float(v) for v in fields[-5:])
            atoms.append((name, resname, resseq, x, y, z, q, r))
    if not atoms:
        raise SystemExit(f"{path}: no ATOM records")
    return atoms


def random_rotation(rng):
    # Uniform random unit quaternion (Shoemake), as a 3x3 matrix.
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    w, x = a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2)
    y, z = b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3)
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input", help="PQR file of one molecule")
    parser.add_argument("copies", type=int, help="number of copies (>= 1)")
    parser.add_argument("output", help="PQR file to write")
    parser.add_argument("--seed", type=int, default=14)
    parser.add_argument("--spacing-factor", type=float, default=1.0)
    args = parser.parse_args()
    if args.copies < 1:
        raise SystemExit("copies must be >= 1")

    atoms = read_pqr(args.input)
    n = len(atoms)
    cx = sum(a[3] for a in atoms) / n
    cy = sum(a[4] for a in atoms) / n
    cz = sum(a[5] for a in atoms) / n
    radius = max(math.dist((a[3], a[4], a[5]), (cx, cy, cz)) + a[7] for a in atoms)
    spacing = 2.0 * radius * args.spacing_factor
    side = math.ceil(args.copies ** (1.0 / 3.0) - 1e-9)

    rng = random.Random(args.seed)
    serial = 0
    with open(args.output, "w") as out:
        out.write(f"REMARK make_assembly.py {args.input} x{args.copies} seed {args.seed}\n")
        for c in range(args.copies):
            i, j, k = c % side, (c // side) % side, c // (side * side)
            offset = (i * spacing, j * spacing, k * spacing)
            rot = random_rotation(rng) if c > 0 else [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
            for name, resname, resseq, x, y, z, q, r in atoms:
                d = (x - cx, y - cy, z - cz)
                p = [sum(rot[row][m] * d[m] for m in range(3)) + offset[row] for row in range(3)]
                serial += 1
                out.write(
                    f"ATOM {serial:7d} {name:<4} {resname:<4} {resseq:>5} "
                    f"{p[0]:10.3f} {p[1]:10.3f} {p[2]:10.3f} {q:7.4f} {r:6.4f}\n"
                )
        out.write("END\n")
    print(f"{args.output}: {serial} atoms, {args.copies} copies, lattice spacing {spacing:.1f} Å")


if __name__ == "__main__":
    main()
