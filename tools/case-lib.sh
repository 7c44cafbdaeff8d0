# case-lib.sh: shell functions shared by every case's Allrun and by the case
# tests. Source it; it sets OpenFOAM's runtime environment itself.
#   granair_mesh DIR            blockMesh (log in DIR/log/blockMesh.log)
#   granair_decompose DIR NP    decomposePar into NP subdomains (skipped for NP=1)
#   granair_run DIR NP APP ...  run APP on the case (serial or mpirun -np NP ... -parallel)
#   granair_liggghts DIR NP ... a stand-alone LIGGGHTS stage (serial or mpirun -np NP;
#                               `liggghts` is build/bin/liggghts: its errors reach stderr)
# Every step logs to DIR/log/<step>.log and, on failure, prints the log tail
# and returns non-zero.
_granair_lib_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=foam-env.sh
. "$_granair_lib_dir/foam-env.sh"

_granair_step() {  # dir logname cmd...
  local dir=$1 name=$2; shift 2
  mkdir -p "$dir/log"
  if ! (cd "$dir" && "$@") >"$dir/log/$name.log" 2>&1; then
    echo "granair: '$*' failed in $dir; last lines of $dir/log/$name.log:" >&2
    tail -n 25 "$dir/log/$name.log" >&2
    return 1
  fi
}

granair_mesh() { _granair_step "$1" blockMesh blockMesh; }

granair_decompose() {
  local dir=$1 np=$2
  [ "$np" -gt 1 ] || return 0
  sed -i "s/^numberOfSubdomains .*/numberOfSubdomains $np;/" "$dir/system/decomposeParDict"
  _granair_step "$dir" decomposePar decomposePar -force
}

granair_run() {
  local dir=$1 np=$2 app=$3; shift 3
  if [ "$np" -gt 1 ]; then
    _granair_step "$dir" "$app" mpirun -np "$np" "$app" -parallel "$@"
  else
    _granair_step "$dir" "$app" "$app" "$@"
  fi
}

granair_liggghts() {
  local dir=$1 np=$2; shift 2
  if [ "$np" -gt 1 ]; then
    _granair_step "$dir" liggghts mpirun -np "$np" liggghts "$@"
  else
    _granair_step "$dir" liggghts liggghts "$@"
  fi
}
