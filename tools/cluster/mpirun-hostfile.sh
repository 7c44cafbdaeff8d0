#!/usr/bin/env bash
# mpirun-hostfile.sh: granairFoam on the nodes of an Open MPI hostfile
# (docs/running-on-a-cluster.md). The case must already be meshed and
# decomposed into NP subdomains (blockMesh; decomposePar with
# numberOfSubdomains NP in system/decomposeParDict).
#
#   tools/cluster/mpirun-hostfile.sh HOSTFILE NP CASE_DIR [extra mpirun options]
#
# The environment granair's programs need (OpenFOAM's WM_PROJECT_DIR, PATH
# with build/bin, Open MPI's settings) is set here by tools/foam-env.sh and
# passed to the remote ranks with -x; nothing has to be sourced on the nodes.
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
hostfile=$1 np=$2 case_dir=$3; shift 3
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../foam-env.sh
. "$here/../foam-env.sh"
n=$(sed -n 's/^ *numberOfSubdomains *\([0-9]*\);.*/\1/p' "$case_dir/system/decomposeParDict")
[ "$n" = "$np" ] || { echo "mpirun-hostfile: $case_dir/system/decomposeParDict has numberOfSubdomains $n; expected $np (run decomposePar again)" >&2; exit 1; }
[ -d "$case_dir/processor0" ] || { echo "mpirun-hostfile: $case_dir has no processor0/: run decomposePar first" >&2; exit 1; }
mkdir -p "$case_dir/log"
# --bind-to core: one rank per core, no migration (each rank does DEM and CFD work).
exec mpirun --hostfile "$hostfile" -np "$np" --bind-to core --map-by core \
  -x PATH -x LD_LIBRARY_PATH -x WM_PROJECT_DIR -x WM_PROJECT -x WM_PROJECT_VERSION -x FOAM_SIGFPE \
  -x PYTHONPATH "$@" \
  granairFoam -case "$case_dir" -parallel 2>&1 | tee "$case_dir/log/granairFoam.log"
