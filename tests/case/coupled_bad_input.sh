#!/usr/bin/env bash
# A bad coupled case stops the whole job, on every rank, with a message that
# names the file/key/particle and a non-zero exit: never a crash or a hang.
# Each variant breaks the smoke case one way and runs it on 2 ranks.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/case-lib.sh"
work=$1 np=${2:-2}
src=$here/../data/smoke
rm -rf "$work"; mkdir -p "$work"
fails=0

variant() {   # name -> a fresh meshed, decomposed copy of the smoke case
  local d=$work/$1
  cp -r "$src" "$d"
  granair_mesh "$d" >/dev/null
  echo "$d"
}
run() {       # dir regex: a clean stop, exit code 1, the message matching regex
  local d=$1 regex=$2
  export EXPECT_RC=1
  sed -i "s/^numberOfSubdomains .*/numberOfSubdomains $np;/" "$d/system/decomposeParDict"
  (cd "$d" && decomposePar -force >/dev/null 2>&1)
  if [ "$np" -gt 1 ]; then
    "$here/../support/expect-failure.sh" "$d" "$regex" mpirun -np "$np" granairFoam -parallel || fails=$((fails+1))
  else
    "$here/../support/expect-failure.sh" "$d" "$regex" granairFoam || fails=$((fails+1))
  fi
}

# a particle outside the CFD mesh (above the 20 mm box top)
d=$(variant outside_mesh)
sed -i 's/^region          domain block 0 0.01 0 0.01 0 0.02 units box/region          domain block 0 0.01 0 0.01 0 0.03 units box/' "$d/dem/in.liggghts"
sed -i 's/^create_atoms    1 single 0.0075 0.0025 0.015 units box/create_atoms    1 single 0.0075 0.0025 0.025 units box/' "$d/dem/in.liggghts"
run "$d" "particle [0-9]+ at \(0.0075 0.0025 0.02[0-9]*\) is outside the CFD mesh"

# CFD deltaT that is not couplingInterval x DEM timestep
d=$(variant timestep_mismatch)
sed -i 's/couplingInterval 50;/couplingInterval 40;/' "$d/constant/couplingProperties"
run "$d" "deltaT = 0.0005 s must equal couplingInterval \(40"

# a missing key
d=$(variant missing_drag)
sed -i '/^drag /d' "$d/constant/couplingProperties"
run "$d" "couplingProperties', key 'drag': missing sub-dictionary"

# an unknown void-fraction model
d=$(variant unknown_model)
sed -i 's/voidFraction { type centre; }/voidFraction { type middle; }/' "$d/constant/couplingProperties"
run "$d" "unknown void-fraction model 'middle'"

# a LIGGGHTS error inside the script
d=$(variant liggghts_error)
sed -i 's/^fix integr all nve\/sphere/fix integr all nve\/spheroid/' "$d/dem/in.liggghts"
run "$d" "LIGGGHTS error: .*[Ii]nvalid fix style"

# missing DEM script
d=$(variant missing_script)
rm "$d/dem/in.liggghts"
run "$d" "in.liggghts"

# strict couplingProperties (issue 13, item 5): a misspelled key, a key given
# twice, a missing ';', a NaN vector
d=$(variant misspelled_key)
sed -i 's/^couplingInterval 50;/couplingIntervall 50;/' "$d/constant/couplingProperties"
sed -i 's/^gravity/couplingInterval 50;\ngravity/' "$d/constant/couplingProperties"
run "$d" "couplingProperties' line 2: unknown key 'couplingIntervall' \(did you mean 'couplingInterval'"

d=$(variant misspelled_subkey)
sed -i 's/voidFraction { type centre; }/voidFraction { type centre; witdh 0.002; }/' "$d/constant/couplingProperties"
run "$d" "unknown key 'voidFraction.witdh' \(did you mean 'type'"

d=$(variant duplicate_key)
echo 'gravity (0 0 -9.81);' >> "$d/constant/couplingProperties"
run "$d" "couplingProperties' line [0-9]+: key 'gravity' given twice \(first on line 3\)"

d=$(variant missing_semicolon)
sed -i 's/^couplingInterval 50;/couplingInterval 50/' "$d/constant/couplingProperties"
run "$d" "key 'couplingInterval' \(line 2\): expected a number, found '50 gravity .*';' missing at the end of line 2"

d=$(variant nan_vector)
sed -i 's/^gravity (0 0 -9.81);/gravity (0 0 nan);/' "$d/constant/couplingProperties"
run "$d" "key 'gravity' \(line 3\): component z of the vector is 'nan', expected finite numbers"

[ $fails -eq 0 ] && echo "coupled_bad_input: every variant stopped cleanly with the expected message" \
  || { echo "coupled_bad_input: $fails variant(s) wrong"; exit 1; }
