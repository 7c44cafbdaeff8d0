#!/usr/bin/env bash
# granair_cg_cli.sh GRANAIRCG WORKDIR: granairCG end to end on tiny dumps
# (all outputs, a dictionary with a command-line override, the plot helper)
# and bad input: each stops with exit code 1 and a message naming the
# option, file or key and what was expected.
set -uo pipefail
cg=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") work=$2
here=$(cd "$(dirname "$0")" && pwd)
plot="$here/../../../coupling/cg/app/plot_cg.py"
py=${GRANAIR_PYTHON:-/usr/bin/python3}
rm -rf "$work"; mkdir -p "$work/d"; cd "$work"
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

for step in 0 100; do
  cat > "d/particles_$step.dump" <<EOT
ITEM: TIMESTEP
$step
ITEM: NUMBER OF ATOMS
3
ITEM: BOX BOUNDS pp pp ff
0 0.01
0 0.01
0 0.01
ITEM: ATOMS id x y z vx vy vz radius mass omegax omegay omegaz
1 0.004 0.005 0.001 0.1 0 0 0.001 1e-5 0 0 1
2 0.006 0.005 0.001 -0.1 0 0 0.001 1e-5 0 0 -1
3 0.005 0.005 0.0027 0 0 -0.2 0.001 1e-5 0 0 0
EOT
  cat > "d/pairs_$step.dump" <<EOT
ITEM: TIMESTEP
$step
ITEM: NUMBER OF ENTRIES
1
ITEM: BOX BOUNDS pp pp ff
0 0.01
0 0.01
0 0.01
ITEM: ENTRIES c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6] c_p[7] c_p[8] c_p[9] c_p[10] c_p[11] c_p[12]
0.004 0.005 0.001 0.006 0.005 0.001 1 2 0 -0.5 0 0
EOT
done

# 1. a good run writes every format; the CSV has the fields
"$cg" --particles 'd/particles_*.dump' --pairs 'd/pairs_*.dump' --dt 1e-5 --coordinates XZ \
      --width 1e-3 --n 20 20 --out out/cg > good.log 2>&1 || fail "good run: exit $?: $(tail -3 good.log)"
for f in out/cg.vti out/cg.h5 out/cg.csv; do [ -s "$f" ] || fail "good run wrote no $f"; done
head -1 out/cg.csv | grep -q '^x,z,number_density,volume_fraction,density,momentum_density_x' || fail "CSV header: $(head -c 120 out/cg.csv)"
head -1 out/cg.csv | grep -q 'stress_zz.*inertial_number.*spin_z' || fail "CSV lacks stress/inertial_number/spin"
grep -q '<ImageData WholeExtent="0 19 0 0 0 19"' out/cg.vti || fail "VTI extent"
grep -q "2 of 2 snapshots" good.log || fail "good run: snapshots: $(cat good.log)"
"$py" "$plot" out/cg.csv --out out/cg.png > plot.log 2>&1 && [ -s out/cg.png ] || fail "plot helper: $(cat plot.log)"

# 2. a dictionary, the command line over it; a window average writes a series
cat > cg.dict <<'EOT'
particles "d/particles_*.dump";
coordinates XYZ;   // overridden below
width 0.5e-3;
min (0 0 0); max (0.01 0.01 0.004);
EOT
"$cg" --dict cg.dict --coordinates O --out out/box --format csv > box.log 2>&1 || fail "dict run: $(tail -3 box.log)"
[ "$(wc -l < out/box_series.csv)" = 3 ] || fail "series: $(cat out/box_series.csv)"
grep -q "window average" box.log || fail "O run: $(cat box.log)"

# 3. bad input: exit code 1 and the message
expect() {  # expect 'pattern' args...
  local pattern=$1; shift
  "$cg" "$@" > bad.log 2>&1; local rc=$?
  if [ $rc -ne 1 ] || ! grep -q -- "$pattern" bad.log; then
    fail "'$*': exit $rc, expected 1 and '$pattern'; got: $(cat bad.log)"
  fi
}
P=(--particles 'd/particles_*.dump')
expect "kernel size missing" "${P[@]}"
expect "unknown option '--widht'" "${P[@]}" --widht 1e-3
expect "command line option --width: expected a finite number, found 'abc'" "${P[@]}" --width abc
expect "particle dump: no file matches 'nothing/\*.dump'" --particles 'nothing/*.dump' --width 1e-3
sed 's/ mass / mess /' d/particles_0.dump > bad_particles.dump
expect "column(s) mass missing" --particles bad_particles.dump --width 1e-3
expect "CG window: x from 0.02 to 0.01 m, expected min < max" "${P[@]}" --width 1e-3 --min 0.02 0 0
expect "unknown coordinates 'XYY'" "${P[@]}" --width 1e-3 --coordinates XYY
expect "option --n: 0 grid points" "${P[@]}" --width 1e-3 --n 0
expect "only the gauss kernel takes a cutoff" "${P[@]}" --kernel lucy --width 1e-3 --cutoff 2
expect "unknown kernel 'gaus'" "${P[@]}" --kernel gaus --width 1e-3
expect "option --centre: missing" "${P[@]}" --width 1e-3 --time-average gauss --time-width 1
expect "no snapshot inside it" "${P[@]}" --width 1e-3 --from 500 --to 600
echo 'widht 1e-3;' > bad.dict
expect "file 'bad.dict', key 'widht': unknown setting" --dict bad.dict "${P[@]}"
expect "no file matches 'd/nothing.dump'" "${P[@]}" --width 1e-3 --pairs d/nothing.dump

if [ $failures -ne 0 ]; then echo "granair_cg_cli: $failures failure(s)"; exit 1; fi
echo "granair_cg_cli: all checks passed"
