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
  line=$(grep "granairFoam: no particles left in the DEM domain at t = " "$log" || true)
  [ -n "$line" ] || { echo "  np$np: no 'no particles left' message"; ok=0; }
  if [ -n "$line" ]; then
    t=$(echo "$line" | sed 's/.* at t = \([^ ]*\) s, after coupling step \([0-9]*\) of.*/\1/')
    k=$(echo "$line" | sed 's/.* at t = \([^ ]*\) s, after coupling step \([0-9]*\) of.*/\2/')
    rows=$(($(wc -l < "$d/postProcessing/timeSeries.csv") - 1))
    last=$(tail -n 1 "$d/postProcessing/timeSeries.csv" | cut -d, -f1)
    [ "$rows" -eq "$k" ] || { echo "  np$np: $rows time-series rows for $k steps"; ok=0; }
    [ "$k" -lt 1000 ] || { echo "  np$np: ran all $k steps: the particle never left"; ok=0; }
    "$GRANAIR_PYTHON" -c "import sys; sys.exit(abs(float('$last') - float('$t')) > 1e-9)" \
      || { echo "  np$np: last row t = $last, stopped at t = $t"; ok=0; }
    { [ -f "$d/$t/U" ] || [ -f "$d/processor0/$t/U" ]; } || { echo "  np$np: no fields at t = $t"; ok=0; }
    echo "  np$np: no particles left at t = $t after $k steps, $rows rows, exit $rc"
  fi
  [ $ok -eq 1 ] || fails=$((fails+1))
done
[ $fails -eq 0 ] && echo "empty_domain: every run ended cleanly" || { echo "empty_domain: $fails run(s) wrong"; exit 1; }
