#!/usr/bin/env bash
# run-case.sh SRC NP WORKDIR APP [APP ARGS...]: copy the case SRC to WORKDIR
# (fresh), mesh it, decompose it for NP ranks and run APP on it. Used by the
# ctest tests that run whole cases; exits non-zero with the log tail on failure.
set -euo pipefail
src=$1 np=$2 work=$3 app=$4; shift 4
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../../tools/case-lib.sh
. "$here/../../tools/case-lib.sh"
rm -rf "$work"; mkdir -p "$(dirname "$work")"; cp -r "$src" "$work"
granair_mesh "$work"
granair_decompose "$work" "$np"
granair_run "$work" "$np" "$app" "$@"
echo "run-case: $app on $np rank(s) finished; log: $work/log/$app.log"
