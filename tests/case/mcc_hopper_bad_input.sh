#!/usr/bin/env bash
# Bad input to granairContinuumFoam stops with the file and key (or patch,
# field, model name) named, never a crash or a hang. Builds the coarsest valid
# MCC hopper case (cases/mcc-hopper, N = 8, a few steps), then breaks it one
# way at a time: WORK/<variant>.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/case-lib.sh"
work=$1
rm -rf "$work"; mkdir -p "$work"
case_dir=$here/../../cases/mcc-hopper
valid=$work/valid
"$case_dir/Allrun" --setup-only --mesh 8 --end 1e-4 --out "$work/setup" > /dev/null
mv "$work/setup/runs/N8" "$valid"
(cd "$valid" && blockMesh >log.blockMesh 2>&1 && setAlphaField >log.setAlphaField 2>&1 && setFields >log.setFields 2>&1)
(cd "$valid" && granairContinuumFoam > log.ok 2>&1) || { echo "the valid case failed:"; tail "$valid/log.ok"; exit 1; }

variant() { rm -rf "$work/$1"; cp -r "$valid" "$work/$1"; rm -rf "$work/$1/postProcessing"; echo "$work/$1"; }
check() { "$here/../support/expect-failure.sh" "$1" "$2" granairContinuumFoam; }
props=constant/granularProperties
fails=0

d=$(variant missing_properties); rm "$d/$props"
check "$d" "cannot open file '.*granularProperties'" || fails=$((fails+1))

d=$(variant missing_muS); sed -i '/muS/d' "$d/$props"
check "$d" "granularProperties', key 'rheology.muS': missing" || fails=$((fails+1))

d=$(variant missing_bulk_density); sed -i 's/^    rho         900;.*//' "$d/$props"
check "$d" "granularProperties', key 'powder.rho': missing" || fails=$((fails+1))

d=$(variant unknown_rheology); sed -i 's/type        muI;/type        muJ;/' "$d/$props"
check "$d" "key 'rheology.type': unknown rheology 'muJ'.*" || fails=$((fails+1))

# latzSchmidt transports the granular temperature: without 0/T it stops naming
# the file; without the particle density it names the key.
latz='type latzSchmidt; c0 0.5579; cMax 0.5771; T0 0.41; eta0 0.00052; lambda0 0.001; eps0 332.84;'
d=$(variant latz_missing_T)
sed -i "s/type        muI;/$latz/" "$d/$props"   # rhoP: the muI block's line
check "$d" "rheology 'latzSchmidt' transports the granular temperature, but its field file '.*0/T' is missing" \
  || fails=$((fails+1))

d=$(variant latz_missing_rhoP)
sed -i "s/type        muI;/$latz/" "$d/$props"; sed -i '/rhoP/d' "$d/$props"
cp "$case_dir/latzSchmidt/0/T" "$d/0/T"
check "$d" "granularProperties', key 'rheology.rhoP': missing" || fails=$((fails+1))

d=$(variant negative_cap); sed -i "s/^\( *etaMax *\)[^;]*;/\1-1;/" "$d/$props"
check "$d" "granularProperties.*etaMax = -1" || fails=$((fails+1))

d=$(variant removed_pressure_floor); sed -i "s/^\( *etaMax *[^;]*;\)/\1 pMin 1;/" "$d/$props"
check "$d" "granularProperties', key 'rheology.pMin': the pressure floor pMin was removed" || fails=$((fails+1))

# dilatancy (Dilatancy.H): only with muI, a positive rate, and rho_b <= rho_p.
d=$(variant dilatancy_latz)
sed -i "s/type        muI;/$latz/" "$d/$props"; sed -i 's/^outletPatch .*/&\ndilatancy on;/' "$d/$props"
cp "$case_dir/latzSchmidt/0/T" "$d/0/T"
check "$d" "key 'dilatancy': dilatancy needs a pressure/shear-rate rheology \\(muI\\); 'latzSchmidt'" || fails=$((fails+1))

d=$(variant dilatancy_bad_rate); sed -i 's/^outletPatch .*/&\ndilatancy on; dilatancyRate -1;/' "$d/$props"
check "$d" "key 'dilatancyRate': value -1 outside \\(0, 1e6\\)" || fails=$((fails+1))

d=$(variant dilatancy_dense_bulk); sed -i 's/^outletPatch .*/&\ndilatancy on;/' "$d/$props"
sed -i 's/^    rho         900;/    rho         2000;/' "$d/$props"
check "$d" "key 'powder.rho': the bulk density 2000 kg/m3 must not exceed the particle density rheology \\{ rhoP \\} 1500" \
  || fails=$((fails+1))

d=$(variant bad_wall_friction); sed -i 's/frictionCoefficient 0.3;/frictionCoefficient -0.3;/' "$d/0/U"
check "$d" "patch wall, field U: frictionCoefficient = -0.3, expected a wall friction coefficient" || fails=$((fails+1))

d=$(variant simplec_key); sed -i 's/^\( *pressureCorrection .*\)$/    consistent yes;\n\1/' "$d/system/fvSolution"
check "$d" "PIMPLE consistent: not used by granairContinuumFoam" || fails=$((fails+1))

d=$(variant bad_outlet_patch); sed -i 's/^outletPatch .*/outletPatch     orifice;/' "$d/$props"
check "$d" "key 'outletPatch': no boundary patch named 'orifice'" || fails=$((fails+1))

d=$(variant unknown_air_model); sed -i 's/model       none;/model       darcy;/' "$d/$props"
check "$d" "key 'air.model': unknown air model 'darcy'" || fails=$((fails+1))

d=$(variant missing_alpha); rm "$d/0/alpha.powder"
check "$d" "0/alpha.powder" || fails=$((fails+1))

# time controls that cannot work (issue 13, item 6; was SIGFPE, exit 136):
# exit 1 with the key named
d=$(variant zero_deltaT); sed -i 's/^deltaT .*/deltaT          0;/' "$d/system/controlDict"
EXPECT_RC=1 check "$d" "controlDict\", key 'deltaT' = 0: expected a time step > 0" || fails=$((fails+1))

d=$(variant zero_maxCo); sed -i 's/^maxCo .*/maxCo           0;/' "$d/system/controlDict"
EXPECT_RC=1 check "$d" "key 'maxCo' = 0: expected a Courant number > 0" || fails=$((fails+1))

[ $fails -eq 0 ] && echo "mcc_hopper_bad_input: all variants stopped with the expected message" \
  || { echo "mcc_hopper_bad_input: $fails variant(s) wrong"; exit 1; }
