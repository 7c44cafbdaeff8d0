#!/usr/bin/env bash
# Bad input to the air solver stops with the file, key or cell named, never a
# crash or a hang. Builds one valid Ergun-bed case, then breaks it one way at
# a time: WORK/<variant>.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/case-lib.sh"
work=$1
rm -rf "$work"; mkdir -p "$work"
valid=$work/valid
"$GRANAIR_PYTHON" -m granair_cases render "$here/../../cases/ergun-packed-bed/template" "$valid" \
  EPS=0.4 END_TIME=0.002 DT=0.001 RHO=1.2 MU=1.8e-5 DRAG_LAW=ErgunGidaspow D=225e-6 U_S=0.01 \
  NP=1 WRITE_EVERY=100000 "INLET_VOIDFRACTION=type zeroGradient;"
(cd "$valid" && blockMesh >log.blockMesh 2>&1 && setFields >log.setFields 2>&1)
(cd "$valid" && granairAirFoam > log.ok 2>&1) || { echo "the valid case failed:"; tail "$valid/log.ok"; exit 1; }

variant() { rm -rf "$work/$1"; cp -r "$valid" "$work/$1"; echo "$work/$1"; }
check() { "$here/../support/expect-failure.sh" "$1" "$2" granairAirFoam; }
fails=0

d=$(variant missing_p); rm "$d/0/p"
check "$d" "0/p" || fails=$((fails+1))

d=$(variant missing_rho); sed -i '/^rho/d' "$d/constant/transportProperties"
check "$d" "rho.*transportProperties|transportProperties.*rho" || fails=$((fails+1))

d=$(variant eps_zero); sed -i 's/voidfraction 0.4/voidfraction 0/' "$d/system/setFieldsDict"; (cd "$d" && setFields >/dev/null 2>&1)
check "$d" "void fraction 0 in cell [0-9]+ at \(" || fails=$((fails+1))

d=$(variant eps_above_one); sed -i 's/voidfraction 0.4/voidfraction 1.5/' "$d/system/setFieldsDict"; (cd "$d" && setFields >/dev/null 2>&1)
check "$d" "void fraction 1.5 in cell [0-9]+ at \(" || fails=$((fails+1))

d=$(variant missing_diameter); sed -i 's/^bed .*/bed { }/' "$d/constant/couplingProperties"
check "$d" "couplingProperties', key 'bed.diameter': missing" || fails=$((fails+1))

d=$(variant unknown_drag); sed -i 's/type ErgunGidaspow;/type Ergun;/' "$d/constant/couplingProperties"
check "$d" "unknown drag law 'Ergun'.*" || fails=$((fails+1))

d=$(variant bad_patch); sed -i 's/low  { type plane;[^}]*}/low { type patch; patch nowhere; normal (0 0 1); }/' "$d/constant/couplingProperties"
check "$d" "monitors.low.patch': no boundary patch 'nowhere'" || fails=$((fails+1))

d=$(variant plane_off_faces); sed -i 's/point (0 0 0.02)/point (0 0 0.0205)/' "$d/constant/couplingProperties"
check "$d" "selects no faces" || fails=$((fails+1))

[ $fails -eq 0 ] && echo "air_bad_input: all variants stopped with the expected message" || { echo "air_bad_input: $fails variant(s) wrong"; exit 1; }
