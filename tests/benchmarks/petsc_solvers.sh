#!/bin/bash
# Side by side on the same matrix (the finest level of one hierarchy): the built-in
# MG-PCG and IC-PCG (`molmesh solve`), and through molmesh-petsc on 1 and 2 MPI ranks
# PCMG on molmesh's levels, PCGAMG, hypre BoomerAMG and ICC. Setup, solve, total (s) and
# CG iterations come from each run's --json. Table for docs/benchmarks.md.
#   usage: [REPEAT=N] petsc_solvers.sh BUILD_DIR HIER.h5 [extra solve options]
# REPEAT=N (default 1) runs every row N times and prints the run with the median total, so
# one run slowed by other load on a shared machine does not decide the row.
set -euo pipefail
build=$1 h5=$2
shift 2
repeat=${REPEAT:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpirun="mpirun --oversubscribe --allow-run-as-root"
row() {  # name json...
  python3 - "$@" <<'PY'
import json, sys
runs = sorted((json.load(open(f)) for f in sys.argv[2:]),
              key=lambda j: j['setup_time_s'] + j['solve_time_s'])
j = runs[len(runs) // 2]
print(f"| {sys.argv[1]} | {j['unknowns']:,} | {j['setup_time_s']:.2f} | {j['solve_time_s']:.2f} | "
      f"{j['setup_time_s'] + j['solve_time_s']:.2f} | {j['iterations']} | "
      f"{j['rate_constant_M-1s-1']:.6e} |")
PY
}
runs() {  # name command... (the command takes --json FILE last)
  local name=$1 files=()
  shift
  for ((i = 0; i < repeat; ++i)); do
    "$@" "$work/run$i.json" > /dev/null
    files+=("$work/run$i.json")
  done
  row "$name" "${files[@]}"
}
echo "| solver | unknowns | setup s | solve s | total s | iterations | rate M⁻¹s⁻¹ |"
echo "|---|---|---|---|---|---|---|"
runs "built-in MG-PCG (molmesh levels)" \
  "$build/tools/molmesh" -q solve smoluchowski "$h5" --no-fields "$@" --json
runs "built-in IC-PCG" \
  "$build/tools/molmesh" -q solve smoluchowski "$h5" --no-fields --preconditioner ic "$@" --json
for ranks in 1 2; do
  for pc in mg gamg hypre icc; do
    # The built-in --preconditioner only decides whether the coarse meshes are read and
    # discretised (in the timed setup); of the PETSc preconditioners only PCMG uses them.
    builtin=()
    [ $pc != mg ] && builtin=(--preconditioner ic)
    runs "PETSc $pc, $ranks rank(s)" \
      $mpirun -n $ranks "$build/tools/molmesh-petsc" -q --pc $pc smoluchowski "$h5" --no-fields \
      "${builtin[@]}" "$@" --json
  done
done
