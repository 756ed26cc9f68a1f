#!/bin/bash
# Side by side on the same matrix (the finest level of one hierarchy): the built-in
# MG-PCG and IC-PCG (`molmesh solve`), and through molmesh-petsc on 1 and 2 MPI ranks
# PCMG on molmesh's levels, PCGAMG, hypre BoomerAMG and ICC. Setup, solve, total (s) and
# CG iterations come from each run's --json. Table for docs/benchmarks.md.
#   usage: petsc_solvers.sh BUILD_DIR HIER.h5 [extra solve options]
set -euo pipefail
build=$1 h5=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mpirun="mpirun --oversubscribe --allow-run-as-root"
row() {  # name json
  python3 - "$1" "$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[2]))
print(f"| {sys.argv[1]} | {j['unknowns']:,} | {j['setup_time_s']:.2f} | {j['solve_time_s']:.2f} | "
      f"{j['setup_time_s'] + j['solve_time_s']:.2f} | {j['iterations']} | "
      f"{j['rate_constant_M-1s-1']:.6e} |")
PY
}
echo "| solver | unknowns | setup s | solve s | total s | iterations | rate M⁻¹s⁻¹ |"
echo "|---|---|---|---|---|---|---|"
"$build/tools/molmesh" -q solve smoluchowski "$h5" --no-fields --json "$work/mg.json" "$@" > /dev/null
row "built-in MG-PCG (molmesh levels)" "$work/mg.json"
"$build/tools/molmesh" -q solve smoluchowski "$h5" --no-fields --preconditioner ic \
  --json "$work/ic.json" "$@" > /dev/null
row "built-in IC-PCG" "$work/ic.json"
for ranks in 1 2; do
  for pc in mg gamg hypre icc; do
    $mpirun -n $ranks "$build/tools/molmesh-petsc" -q --pc $pc smoluchowski "$h5" --no-fields \
      --json "$work/$pc$ranks.json" "$@" > /dev/null
    row "PETSc $pc, $ranks rank(s)" "$work/$pc$ranks.json"
  done
done
