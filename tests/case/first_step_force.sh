#!/usr/bin/env bash
# The fluid force at the first coupling step of a packed column matches Ergun
# (no start-up kick from a void fraction that ignores the particles present at
# the start), on NP ranks. Usage: first_step_force.sh WORKDIR NP
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1 np=$2
"$here/../support/run-case.sh" "$here/../data/packed-column" "$np" "$work" granairFoam
. "$here/../../tools/foam-env.sh"
"$GRANAIR_PYTHON" "$here/first_step_force.py" "$work"
