#!/usr/bin/env bash
# An emptied DEM domain is a normal end (an emptied silo): once every particle
# has left, granairFoam stops before its end time with a message that says so,
# exit code 0, the time series has one row per step done and ends at the stop
# time, and the fields of that time are written. (LIGGGHTS 3.8 cannot `run`
# with zero atoms: without this the next DEM advance stopped with "Atom types
# must start from 1".) The particle-in-stream case with its end time raised to
# 1 s: the stream carries the particle out through the box top at t ~ 0.5 s.
# Serial and on 2 ranks.
# Usage: empty_domain.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
. "$here/../../tools/case-lib.sh"
. "$here/end_checks.sh"
rm -rf "$work"; mkdir -p "$work"
fails=0

for np in 1 2; do
  d=$work/np$np
  cp -r "$here/../data/particle-in-stream" "$d"
  sed -i 's/endTime 0.1;/endTime 1;/' "$d/system/controlDict"
  granair_mesh "$d"
  granair_decompose "$d" "$np"
  rc=0
  if [ "$np" -eq 1 ]; then
    (cd "$d" && granairFoam > log/run.log 2>&1) || rc=$?
  else
    (cd "$d" && mpirun -np 2 granairFoam -parallel > log/run.log 2>&1) || rc=$?
  fi
  log=$d/log/run.log ok=1
  tail -n 5 "$log"
  [ "$rc" -eq 0 ] || { echo "  np$np: exit $rc, expected 0"; ok=0; }
  granair_check_end "np$np" "$d" "granairFoam: no particles left in the DEM domain" || ok=0
  [ -z "$END_K" ] || [ "$END_K" -lt 1000 ] || { echo "  np$np: ran all $END_K steps: the particle never left"; ok=0; }
  grep -q "The outputs are complete up to that time" "$log" || { echo "  np$np: no 'outputs complete' line"; ok=0; }
  [ $ok -eq 1 ] || fails=$((fails+1))
done
[ $fails -eq 0 ] && echo "empty_domain: every run ended cleanly" || { echo "empty_domain: $fails run(s) wrong"; exit 1; }
