#!/usr/bin/env bash
# SIGINT / SIGTERM end granairFoam cleanly (issue 13, item 7): the coupling
# step in hand is finished, the message says where the run stopped and that
# the outputs are complete, the time series has exactly one row per step
# done, the fields of the stop time are written, and the exit code is
# 128 + signal; no rank hangs. Runs the particle-in-stream case (endTime
# raised to 100 s, far beyond the test) and signals it once it has run
# a few steps:
#   serial, SIGINT to granairFoam                      -> exit 130
#   2 ranks, SIGTERM to one rank (a batch system
#   signals the ranks; the others follow)              -> mpirun exits 143
#   2 ranks, SIGTERM to mpirun (it passes SIGTERM on to
#   the ranks after odls_base_sigkill_timeout seconds
#   and exits 1 itself: Open MPI's rule)               -> the ranks stop cleanly
# Usage: stop_signal.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
. "$here/../../tools/case-lib.sh"
. "$here/end_checks.sh"
rm -rf "$work"; mkdir -p "$work"
fails=0

start() {   # name np -> a fresh case dir in $d
  d=$work/$1
  cp -r "$here/../data/particle-in-stream" "$d"
  sed -i 's/endTime 0.1;/endTime 100;/' "$d/system/controlDict"
  # The stream carries the particle up and out of the box top (z = 0.3 m) at
  # t ~ 0.5 s; a run that outlives that (SIGTERM to mpirun is passed on only
  # after Open MPI's 1 s timeout, and a quiet machine runs ~0.5 s of this case
  # in it) would end with no particle in LIGGGHTS instead of the signal. A
  # ceiling holds it inside for the whole test.
  sed -i 's|^fix integr all nve/sphere|&\nfix ceiling all wall/gran model hertz tangential history primitive type 1 zplane 0.29|' "$d/dem/in.liggghts"
  grep -q '^fix ceiling' "$d/dem/in.liggghts"
  granair_mesh "$d"
  granair_decompose "$d" "$2"
}
wait_rows() {   # wait until the time series has >= 5 rows (at most 120 s)
  local i
  for i in $(seq 1 600); do
    [ -f "$d/postProcessing/timeSeries.csv" ] && [ "$(wc -l < "$d/postProcessing/timeSeries.csv")" -gt 5 ] && return 0
    sleep 0.2
  done
  echo "stop_signal: the run did not start" >&2; return 1
}
check() {   # name rc expected_rc signal_name
  local name=$1 rc=$2 want=$3 sig=$4 log=$d/log/run.log
  local ok=1
  tail -n 4 "$log"
  [ "$rc" -eq "$want" ] || { echo "  $name: exit $rc, expected $want"; ok=0; }
  granair_check_end "$name" "$d" "granairFoam: stopped by $sig" || ok=0
  grep -q "The outputs are complete up to that time" "$log" || { echo "  $name: no 'outputs complete' line"; ok=0; }
  echo "  $name: exit $rc"
  [ $ok -eq 1 ] || fails=$((fails+1))
}

# serial, SIGINT
start serial_sigint 1
(cd "$d" && exec granairFoam > log/run.log 2>&1) & pid=$!
wait_rows; kill -INT $pid; rc=0; wait $pid || rc=$?
check serial_sigint $rc 130 SIGINT

# 2 ranks, SIGTERM to one rank
start np2_sigterm_rank 2
(cd "$d" && exec mpirun -np 2 granairFoam -parallel > log/run.log 2>&1) & pid=$!
wait_rows; kill -TERM "$(pgrep -P $pid granairFoam | tail -n 1)"; rc=0; wait $pid || rc=$?
check np2_sigterm_rank $rc 143 SIGTERM

# 2 ranks, SIGTERM to mpirun: Open MPI passes it on after
# odls_base_sigkill_timeout seconds (default 1 s) and SIGKILLs as long after:
# enough for a step of this small case
start np2_sigterm_mpirun 2
(cd "$d" && exec mpirun -np 2 granairFoam -parallel > log/run.log 2>&1) & pid=$!
wait_rows; kill -TERM $pid; rc=0; wait $pid || rc=$?
check np2_sigterm_mpirun $rc 1 SIGTERM

[ $fails -eq 0 ] && echo "stop_signal: every run stopped cleanly" || { echo "stop_signal: $fails run(s) wrong"; exit 1; }
