#!/bin/bash
# Accuracy at the hierarchy defaults (docs/validation.md): the absorbing sphere (R 10 A,
# outer 100 A) and the Born ion (a 3 A, outer 60 A) through `molmesh hierarchy` and
# `molmesh solve`, with the given extra hierarchy options; one line of errors, sizes, times.
# usage: accuracy_defaults.sh MOLMESH TAG [hierarchy options...]   (run in a scratch folder)
set -euo pipefail
M=$1 tag=$2
shift 2
echo "ATOM      1  NA  ION     1       0.000   0.000   0.000  1.0000 10.0" > sphere.pqr
echo "ATOM      1  I   ION     1       0.000   0.000   0.000  1.00  3.00" > born.pqr
s0=$(date +%s.%N)
$M -q hierarchy sphere.pqr -o s_$tag.h5 --domain exterior --outer-radius 100 "$@" > /dev/null
s1=$(date +%s.%N)
$M -q solve smoluchowski s_$tag.h5 --json s_$tag.json --no-fields > /dev/null
b0=$(date +%s.%N)
$M -q hierarchy born.pqr -o b_$tag.h5 --domain full --outer-radius 60 "$@" > /dev/null
b1=$(date +%s.%N)
$M -q solve poisson b_$tag.h5 --pqr born.pqr --json b_$tag.json --no-fields > /dev/null
python3 - "$tag" "$s0" "$s1" "$b0" "$b1" <<'PY'
import json,sys
tag,s0,s1,b0,b1=sys.argv[1],*map(float,sys.argv[2:])
s=json.load(open(f"s_{tag}.json")); b=json.load(open(f"b_{tag}.json"))
k=s["rate_constant_M-1s-1"]; dg=b["solvation_energy_kJ_per_mol"]
print(f"{tag}: sphere {100*(k/8.4085e9-1):+.2f}% ({s['tetrahedra']} tets, hier {s1-s0:.1f}s, solve {s['total_time_s']:.2f}s, {s['iterations']} it) | born {100*(dg/-228.61-1):+.2f}% ({b['tetrahedra']} tets, hier {b1-b0:.1f}s, solve {b['total_time_s']:.2f}s, {b['iterations']} it)")
PY
