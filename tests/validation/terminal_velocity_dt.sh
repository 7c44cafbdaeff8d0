#!/usr/bin/env bash
# Terminal velocity of one sphere in a stream: dt_CFD = 1e-3 vs 1e-5 s within
# 0.5 % for every void-fraction model (terminal_velocity_dt.py). Usage: terminal_velocity_dt.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/foam-env.sh"
rm -rf "$1"; mkdir -p "$1"
exec "$GRANAIR_PYTHON" "$here/terminal_velocity_dt.py" "$1"
