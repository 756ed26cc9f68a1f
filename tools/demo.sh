#!/usr/bin/env bash
# The main job on a bundled molecule: fasciculin-2 (examples/fas2.pqr) to a surface mesh
# with quality statistics. Usage: demo.sh MOLMESH_BINARY EXAMPLES_DIR OUTPUT_DIR
set -euo pipefail
molmesh="$1"; examples="$2"; out="$3"
"$molmesh" surface "$examples/fas2.pqr" -o "$out/fas2.off" --stats "$out/fas2.surface.json"
echo "molmesh: demo outputs in $out"
ls -l "$out"
