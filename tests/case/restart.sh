#!/usr/bin/env bash
# Restart (issue 13, item 4): on NP ranks, a deterministic run of 2T (run A:
# 0 -> 4 ms) equals T + restart + T (run B: 0 -> 2 ms, then startFrom
# latestTime to 4 ms) to round-off: time series (no row lost or repeated),
# air pressure, particles and accounting (restart_check.py). With
# MISMATCH=1 also the refusals, each with its message and exit code 1:
#   - a restart script that does not read the restart point (DEM step 0, the
#     restart point's is 200): "DEM and CFD times do not match";
#   - a start at a time an earlier run passed, without a restart point;
#   - an incomplete restart point (no 'coupling' file).
# Usage: restart.sh WORKDIR NP [MISMATCH]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1 np=$2 mismatch=${3:-0}
. "$here/../../tools/case-lib.sh"
src=$here/../data/restart-column
rm -rf "$work"; mkdir -p "$work"
for run in A B; do
  cp -r "$src" "$work/$run"
  granair_mesh "$work/$run"
  granair_decompose "$work/$run" "$np"
done
B=$work/B
sed -i 's/endTime 0.004;/endTime 0.002;/' "$B/system/controlDict"
granair_run "$work/A" "$np" granairFoam
granair_run "$B" "$np" granairFoam
cp "$B/log/granairFoam.log" "$B/log/granairFoam.first.log"
sed -i 's/startFrom startTime;/startFrom latestTime;/; s/endTime 0.002;/endTime 0.004;/' "$B/system/controlDict"
granair_run "$B" "$np" granairFoam
grep -q "4 coupling steps from t = 0.002 s" "$B/log/granairFoam.log" \
  || { echo "restart: the second part of run B did not start at t = 0.002 s"; exit 1; }
"$GRANAIR_PYTHON" "$here/restart_check.py" "$work/A" "$B"

[ "$mismatch" = 1 ] || exit 0
export EXPECT_RC=1
fails=0
refused() {   # name regex: a copy of B after its first part, changed by the caller
  local d=$1 regex=$2
  if [ "$np" -gt 1 ]; then
    "$here/../support/expect-failure.sh" "$d" "$regex" mpirun -np "$np" granairFoam -parallel || fails=$((fails+1))
  else
    "$here/../support/expect-failure.sh" "$d" "$regex" granairFoam || fails=$((fails+1))
  fi
}
first_part() {   # name -> a copy of B as it was after its first part (0 -> 2 ms)
  local d=$work/$1
  rm -rf "$d"; cp -r "$B" "$d"
  rm -rf "$d/0.004" "$d"/processor*/0.004 "$d/restart/0.004"
  echo "$d"
}
# the csv of the first part: its 4 rows
trim() { head -n 5 "$1/postProcessing/timeSeries.csv" > "$1/t.csv" && mv "$1/t.csv" "$1/postProcessing/timeSeries.csv"; }

d=$(first_part wrong_script); trim "$d"
sed -i 's|restartScript dem/in.restart;|restartScript dem/in.liggghts;|' "$d/constant/couplingProperties"
refused "$d" "restart: DEM and CFD times do not match\. The CFD starts at t = 0\.002 s, whose restart point .*restart/0\.002/coupling has LIGGGHTS at step 200 .* after the restart script dem/in.liggghts LIGGGHTS is at step 0 .*read_restart \\$\{granair_restart\}"

d=$(first_part no_restart_point); trim "$d"; rm -rf "$d/restart/0.002"
refused "$d" "starts at t = 0\.002 s, a time an earlier run of this case passed .* but there is no restart point"

d=$(first_part incomplete); trim "$d"; rm "$d/restart/0.002/coupling"
refused "$d" "restart/0\.002 has no 'coupling' file: the restart point of t = 0\.002 s is incomplete"

[ $fails -eq 0 ] && echo "restart: every mismatch refused with its message" || { echo "restart: $fails refusal(s) wrong"; exit 1; }
