#!/usr/bin/env bash
# A particle released at rest in a uniform upward air stream (one-way
# coupling, CFD step 1 ms): velocity history within 1 % of RK4 from the first
# output on, and the air left exactly the inflow field (particle_in_stream.py).
# Usage: particle_in_stream.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
"$here/../support/run-case.sh" "$here/../data/particle-in-stream" 1 "$work" granairFoam
. "$here/../../tools/foam-env.sh"
"$GRANAIR_PYTHON" "$here/particle_in_stream.py" "$work"
