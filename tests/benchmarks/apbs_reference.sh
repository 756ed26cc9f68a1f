#!/usr/bin/env bash
# APBS mg-auto reference solvation energies (kJ/mol) of the tests/data molecules, and how
# they converge with the fine-grid spacing: the numbers in docs/surface.md, "APBS".
#   tests/benchmarks/apbs_reference.sh MOLECULE SRAD DIME...   e.g. 1a1p 1.4 97 129 161 193
# pdie 2, sdie 78.54, no ions, srfm smol (srad 0: the vdW surface), chgm spl2; the energy is
# the run with sdie 78.54 minus the run with sdie 2. Fine box = the atoms' extent + 10 Å per
# axis, coarse box twice that. Prints "dime spacing energy".
set -euo pipefail
here=$(cd "$(dirname "$0")/../data" && pwd)
mol=$1 srad=$2; shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here/$mol.pqr" "$work/"
read -r fx fy fz < <(awk '/^(ATOM|HETATM)/ {x=substr($0,31,8)+0; y=substr($0,39,8)+0; z=substr($0,47,8)+0;
  if (n++ == 0) {ax=bx=x; ay=by=y; az=bz=z}
  if (x<ax) ax=x; if (x>bx) bx=x; if (y<ay) ay=y; if (y>by) by=y; if (z<az) az=z; if (z>bz) bz=z}
  END {printf "%.1f %.1f %.1f\n", bx-ax+10, by-ay+10, bz-az+10}' "$work/$mol.pqr")
for dime in "$@"; do
  block() {
    cat <<EOB
elec name $1
  mg-auto
  dime $dime $dime $dime
  cglen $(echo "$fx*2" | bc) $(echo "$fy*2" | bc) $(echo "$fz*2" | bc)
  fglen $fx $fy $fz
  cgcent mol 1
  fgcent mol 1
  mol 1
  lpbe
  bcfl mdh
  pdie 2.0
  sdie $2
  srfm smol
  chgm spl2
  sdens 10.0
  srad $srad
  swin 0.3
  temp 298.15
  calcenergy total
  calcforce no
end
EOB
  }
  { echo "read"; echo "  mol pqr $mol.pqr"; echo "end"; block solv 78.54; block ref 2.0
    echo "print elecEnergy solv - ref end"; echo "quit"; } > "$work/in.apbs"
  (cd "$work" && apbs in.apbs > out.txt 2> err.txt) || { cat "$work/err.txt" >&2; exit 1; }
  energy=$(sed -n 's/.*Global net ELEC energy = *\([-+0-9.eE]*\).*/\1/p' "$work/out.txt" | tail -1)
  printf "%s %.4f %.2f\n" "$dime" "$(echo "$fx/($dime-1)" | bc -l)" "$energy"
done
