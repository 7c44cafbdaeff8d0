#!/usr/bin/env bash
# Rank independence of the coupled run: the short run (Allrun --quick: the
# settled bed at 0.5 U_mf, then fluidised at 2 U_mf) on 1 and on 2 ranks from
# the same settled bed, compared by compare_ranks.py (see README.md).
#
#   ./rank_independence.sh OUT_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:?usage: rank_independence.sh OUT_DIR}
mkdir -p "$out"
out=$(cd "$out" && pwd)
# The centre void fraction: a bead's volume goes to the cell holding its
# centre whatever the decomposition (divided counts satellite points beyond a
# processor boundary in the centre cell, a documented approximation that
# would mask round-off-level agreement).
"$here/Allrun" --quick --check --np 1 --voidfraction centre --out "$out/np1"
"$here/Allrun" --quick --check --np 2 --voidfraction centre --out "$out/np2" \
  --bed "$out/np1/run/dem/bed.restart"
# shellcheck source=../../tools/foam-env.sh
. "$here/../../tools/foam-env.sh"
"$GRANAIR_PYTHON" "$here/compare_ranks.py" "$out/np1/run" "$out/np2/run"
