#!/usr/bin/env bash
# granairFoam writes the void fraction of the particles at the start time to
# the start time directory, with the air on (serial) and off (DEM only, on 2
# ranks): the packed column's bed cells hold 27 spheres of 1 mm in 27 mm3,
# eps = 1 - pi/6, the cells above it 1. Usage: start_void_fraction.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
. "$here/../../tools/case-lib.sh"
rm -rf "$work"; mkdir -p "$work"
for variant in air_on_np1 air_off_np2; do
  d=$work/$variant
  cp -r "$here/../data/packed-column" "$d"
  # fields in ascii at full precision; one coupling step
  sed -i 's/writeFormat binary; writePrecision 8;/writeFormat ascii; writePrecision 17;/; s/endTime 0.001;/endTime 0.0005;/' \
    "$d/system/controlDict"
  np=1
  if [ "$variant" = air_off_np2 ]; then
    sed -i 's/^air on;/air off;/' "$d/constant/couplingProperties"
    np=2
  fi
  granair_mesh "$d"
  granair_decompose "$d" "$np"
  granair_run "$d" "$np" granairFoam
done
"$GRANAIR_PYTHON" "$here/start_void_fraction.py" "$work/air_on_np1" "$work/air_off_np2"
