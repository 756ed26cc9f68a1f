#!/bin/sh
# Sample run (GAMer §4.4): acetylcholine-like ligand (z = +1, D = 1e-5 cm^2/s) diffusing to
# the active-site gorge of mAChE. The gorge (examples/mache-gorge.spheres) absorbs, the rest
# of the molecular surface reflects, the outer sphere (150 Å) holds the bulk. The rate
# constant is computed without and with the electrostatic potential from Debian's apbs
# (examples/mache-apbs.in); the concentration field goes into the HDF5 file (open
# OUT/mache.xdmf in ParaView) and, if python3-matplotlib is present, a PNG slice.
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(dirname "$HERE")
MOLMESH=${MOLMESH:-$ROOT/build/tools/molmesh}
OUT=${OUT:-$ROOT/build/mache-diffusion}
mkdir -p "$OUT"
cp "$ROOT/tests/data/mache.pqr" "$OUT/mache.pqr"
"$MOLMESH" hierarchy "$OUT/mache.pqr" -o "$OUT/mache.h5" --domain exterior --outer-radius 150 \
  --active-site "$HERE/mache-gorge.spheres" --t0 0.1,0.3,0.5,0.7
(cd "$OUT" && apbs "$HERE/mache-apbs.in" > apbs.log)
# Debian's apbs names the file mache-potential-PE0.dx (one file per processor).
POT="$OUT/mache-potential.dx"
[ -f "$POT" ] || POT="$OUT/mache-potential-PE0.dx"
"$MOLMESH" solve smoluchowski "$OUT/mache.h5" --absorbing active-site --diffusion 1e-5 \
  --json "$OUT/rate-no-potential.json"
"$MOLMESH" solve smoluchowski "$OUT/mache.h5" --absorbing active-site --diffusion 1e-5 \
  --potential "$POT" --charge 1 --json "$OUT/rate-potential.json"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "$HERE/plot_concentration.py" "$OUT/mache.h5" "$OUT/mache-concentration.png"
fi
