#!/usr/bin/env bash
# Rank independence of the coupled run (the ctest mpi/coupled/fluidised_bed_rank_independence):
# the short run on 1 and on 2 ranks from the same settled bed, compared (study.py,
# README.md).   ./rank_independence.sh OUT_DIR
set -euo pipefail
exec "$(cd "$(dirname "$0")" && pwd)/Allrun" --rank-independence --check --out "${1:?usage: rank_independence.sh OUT_DIR}"
