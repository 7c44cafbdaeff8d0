#!/usr/bin/env bash
# A stand-alone LIGGGHTS stage (as the cases' fill steps run it, here through
# tools/case-lib.sh's granair_liggghts, with its screen and log in files) shows LIGGGHTS' error
# on stderr and exits 1 (issue 13, item 8): an Error::one (a seed that is not
# a prime > 10000: MPI_Abort) and an Error::all (an unknown fix style), on 1
# and 2 ranks. `liggghts` on granair's PATH is build/bin/liggghts
# (dem-side/applications/liggghts.cpp). Usage: liggghts_stage_error.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
. "$here/../../tools/case-lib.sh"
rm -rf "$work"; mkdir -p "$work"
[ "$(command -v liggghts)" = "$GRANAIR_BUILD/bin/liggghts" ] \
  || { echo "liggghts_stage_error: 'liggghts' is $(command -v liggghts), not $GRANAIR_BUILD/bin/liggghts"; exit 1; }
fails=0
stage() {   # name np regex; the script is $work/<name>/in.stage
  local d=$work/$1 np=$2 regex=$3 out rc=0
  out=$(granair_liggghts "$d" "$np" -in in.stage -log log/log.liggghts -screen log/screen.liggghts 2>&1) || rc=$?
  if [ $rc -ne 1 ] || ! printf '%s\n' "$out" | grep -Eq -- "$regex"; then
    printf '%s\n' "$out" | tail -n 20
    echo "  $1 (np $np): exit $rc, expected 1 and /$regex/"; fails=$((fails+1))
  else
    echo "  $1 (np $np): exit 1, $(printf '%s\n' "$out" | grep -E -m1 -- "$regex")"
  fi
}
setup='atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region domain block 0 0.01 0 0.01 0 0.02 units box
create_box 1 domain
neighbor 0.0005 bin
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5'
for np in 1 2; do
  d=$work/bad_seed_np$np; mkdir -p "$d"
  printf '%s\n%s\n' "$setup" \
    'fix pts all particletemplate/sphere 1234 atom_type 1 density constant 2500 radius constant 0.0005' > "$d/in.stage"
  stage bad_seed_np$np $np "LIGGGHTS error: ERROR on proc 0: Random number generation: .*seed value is > 10000 and a prime number"
  d=$work/bad_fix_np$np; mkdir -p "$d"
  printf '%s\n%s\n' "$setup" 'fix integr all nve/spheroid' > "$d/in.stage"
  stage bad_fix_np$np $np "LIGGGHTS error: ERROR: Invalid fix style: \"nve/spheroid\".*see log/log.liggghts"
done
[ $fails -eq 0 ] && echo "liggghts_stage_error: every stage showed its LIGGGHTS error" \
  || { echo "liggghts_stage_error: $fails stage(s) wrong"; exit 1; }
