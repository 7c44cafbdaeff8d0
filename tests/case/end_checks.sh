# end_checks.sh: what every early end of granairFoam must leave behind (a stop
# signal, case/stop_signal; no particles left, case/empty_domain). Source it.
#   granair_check_end NAME DIR MESSAGE
#     the log DIR/log/run.log has the line "MESSAGE at t = T s, after coupling
#     step K of ..."; the time series has exactly K rows and its last is t = T;
#     the fields of T are written. Prints what is wrong; returns 1 if anything
#     is; sets END_T and END_K.
granair_check_end() {
  local name=$1 d=$2 message=$3 log=$2/log/run.log ok=0 line rows last
  END_T= END_K=
  line=$(grep "$message at t = " "$log" || true)
  [ -n "$line" ] || { echo "  $name: no '$message' message"; return 1; }
  END_T=$(echo "$line" | sed 's/.* at t = \([^ ]*\) s, after coupling step \([0-9]*\) of.*/\1/')
  END_K=$(echo "$line" | sed 's/.* at t = \([^ ]*\) s, after coupling step \([0-9]*\) of.*/\2/')
  rows=$(($(wc -l < "$d/postProcessing/timeSeries.csv") - 1))
  last=$(tail -n 1 "$d/postProcessing/timeSeries.csv" | cut -d, -f1)
  [ "$rows" -eq "$END_K" ] || { echo "  $name: $rows time-series rows for $END_K steps"; ok=1; }
  "$GRANAIR_PYTHON" -c "import sys; sys.exit(abs(float('$last') - float('$END_T')) > 1e-9)" \
    || { echo "  $name: last row t = $last, ended at t = $END_T"; ok=1; }
  { [ -f "$d/$END_T/U" ] || [ -f "$d/processor0/$END_T/U" ]; } || { echo "  $name: no fields at t = $END_T"; ok=1; }
  echo "  $name: ended at t = $END_T after $END_K steps, $rows rows"
  return $ok
}
