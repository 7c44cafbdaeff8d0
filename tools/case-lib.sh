# case-lib.sh: the case layer's runner for shell scripts (the case tests,
# bench/). Source it; it sets OpenFOAM's runtime environment itself.
#   granair_mesh DIR            blockMesh (log in DIR/log/blockMesh.log)
#   granair_decompose DIR NP    decomposePar into NP subdomains (skipped for NP=1)
#   granair_run DIR NP APP ...  run APP on the case (serial or mpirun -np NP ... -parallel)
#   granair_liggghts DIR NP ... a stand-alone LIGGGHTS stage (serial or mpirun -np NP;
#                               `liggghts` is build/bin/liggghts: its errors reach stderr)
# Every step logs to DIR/log/<step>.log and, on failure, prints the log tail
# and returns non-zero (tools/granair_cases/runner.py does the work).
_granair_lib_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=foam-env.sh
. "$_granair_lib_dir/foam-env.sh"

granair_mesh() { "$GRANAIR_PYTHON" -m granair_cases mesh "$1"; }
granair_decompose() { "$GRANAIR_PYTHON" -m granair_cases decompose "$1" "$2"; }
granair_run() { "$GRANAIR_PYTHON" -m granair_cases run "$@"; }
granair_liggghts() { "$GRANAIR_PYTHON" -m granair_cases liggghts "$@"; }
