#!/usr/bin/env bash
# settled_column.sh WORKDIR GRANAIRCG: settle a column in LIGGGHTS with the CG
# dump snippet, run granairCG on its dumps, check statics (settled_column.py).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1 cg=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
py=${GRANAIR_PYTHON:-/usr/bin/python3}
rm -rf "$work"
"$py" "$here/settled_column.py" prepare "$work"
cd "$work"
start=$SECONDS
liggghts -in in.column -log log.liggghts -echo none > screen.liggghts 2>&1 \
  || { tail -20 screen.liggghts; echo "settled_column: LIGGGHTS failed (log: $work/log.liggghts)"; exit 1; }
echo "settled_column: LIGGGHTS $((SECONDS - start)) s"
"$cg" --particles 'cg/particles_*.dump' --pairs 'cg/pairs_*.dump' --walls 'cg/walls_*.dump' --dt 1e-5 \
      --coordinates Z --kernel gauss --width 1e-3 --min 0 0 -0.006 --max 0.02 0.02 0.06 --n 264 \
      --format csv h5 --out cg_z
"$py" "$here/settled_column.py" check "$work"
