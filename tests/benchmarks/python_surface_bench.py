#!/usr/bin/env python3
"""molmesh.surface from Python vs `molmesh surface` (the CLI), same input, same work.

Both sides read the molecule, run the surface pipeline with default options and write
the mesh (.off); the CLI is timed as a whole process, Python as read_atoms + surface +
write inside one interpreter (the module is imported once, before timing). Two pairs, each
the same work on both sides:
  measured    Python's default (per-stage stats and distances in .report) against the CLI
              with --stats;
  unmeasured  measure=False against the CLI's default (no --stats).
Runs alternate (CLI, Python, CLI, ...) so load drifts hit both; medians are reported.

  PYTHONPATH=build/python /usr/bin/python3 tests/benchmarks/python_surface_bench.py \
      --cli build/tools/molmesh --input tests/data/mache.pqr --runs 3
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import molmesh


def run_pair(args, tmp, measured):
    cli_out = os.path.join(tmp, "cli.off")
    py_out = os.path.join(tmp, "py.off")
    stats = ["--stats", os.path.join(tmp, "cli.json")] if measured else []
    cli_s, py_s = [], []
    for _ in range(args.runs):
        start = time.perf_counter()
        subprocess.run([args.cli, "-q", "surface", args.input, "-o", cli_out] + stats,
                       check=True)
        cli_s.append(time.perf_counter() - start)
        start = time.perf_counter()
        atoms = molmesh.read_atoms(args.input)
        surface = molmesh.surface(atoms, measure=measured)
        surface.write(py_out)
        py_s.append(time.perf_counter() - start)
    cli, py = statistics.median(cli_s), statistics.median(py_s)
    return {
        "cli_wall_s": cli_s,
        "python_wall_s": py_s,
        "cli_median_s": cli,
        "python_median_s": py,
        "python_over_cli": py / cli,
        "identical_output": open(cli_out, "rb").read() == open(py_out, "rb").read(),
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--input", required=True)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    result = {"input": args.input, "runs": args.runs}
    with tempfile.TemporaryDirectory() as tmp:
        result["measured"] = run_pair(args, tmp, True)
        result["unmeasured"] = run_pair(args, tmp, False)
    result["load_average"] = os.getloadavg()
    json.dump(result, sys.stdout, indent=2)
    print()


if __name__ == "__main__":
    main()
