#!/usr/bin/env bash
# granairFoam's particle output on 2 ranks: the smoke case with
# `output { vtkInterval 0.0012; }` and 6 coupling steps of 0.0005 s writes the
# particles at the start, at the first coupling step at or after each multiple
# of the interval, and at the end (t = 0, 0.0015, 0.0025, 0.003); each output
# indexes one piece per rank and holds all 3 particles; Ksl and Us land in the
# time directories with U and p. A non-positive interval stops the run with
# the key named.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/case-lib.sh"
work=$1
rm -rf "$work"; mkdir -p "$work"
d=$work/run
cp -r "$here/../data/smoke" "$d"
echo 'output { vtkInterval 0.0012; }' >> "$d/constant/couplingProperties"
sed -i -e 's/endTime 0.001;/endTime 0.003;/' -e 's/writeInterval 1000;/writeInterval 2;/' "$d/system/controlDict"
granair_mesh "$d"
granair_decompose "$d" 2
granair_run "$d" 2 granairFoam

fails=0
expect() {  # description, command...
  local what=$1; shift
  if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; fails=$((fails+1)); fi
}
out=$d/postProcessing/particles
times=$(grep -o 'timestep="[^"]*"' "$out/particles.pvd" | tr -d '"' | sed 's/timestep=//' | tr '\n' ' ')
expect "pvd times are '0 0.0015 0.0025 0.003' (got '$times')" [ "$times" = "0 0.0015 0.0025 0.003 " ]
for k in 0 1 2 3; do
  pieces=$(grep -c '<Piece Source=' "$out/particles_$k.pvtp")
  expect "particles_$k.pvtp indexes 2 pieces (got $pieces)" [ "$pieces" -eq 2 ]
  n=0
  for r in 0 1; do
    m=$(grep -a -o 'NumberOfPoints="[0-9]*"' "$out/particles_$k/rank$r.vtp" | tr -dc '0-9')
    n=$((n + m))
  done
  expect "output $k holds the 3 particles over both pieces (got $n)" [ "$n" -eq 3 ]
done
for f in Ksl Us voidfraction U p; do
  expect "processor0/0.001/$f written" [ -f "$d/processor0/0.001/$f" ]
done

bad=$work/bad_interval
cp -r "$d" "$bad"
sed -i 's/vtkInterval 0.0012;/vtkInterval -1;/' "$bad/constant/couplingProperties"
expect "vtkInterval -1 stops the run naming the key" \
  "$here/../support/expect-failure.sh" "$bad" "key 'output.vtkInterval'.*expected a positive interval" \
  mpirun -np 2 granairFoam -parallel

[ $fails -eq 0 ] && echo "particle_output: all checks passed" || { echo "particle_output: $fails check(s) failed"; exit 1; }
