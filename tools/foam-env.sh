# foam-env.sh: OpenFOAM's runtime environment for granair (sourced by the
# launcher and by case scripts; users never need to source it by hand).
# Debian's OpenFOAM has no etc/ directory; its programs read etc/controlDict
# from WM_PROJECT_DIR, which we point at the header tree the installer made.
_granair_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export GRANAIR_ROOT="${GRANAIR_ROOT:-$_granair_root}"
export GRANAIR_BUILD="${GRANAIR_BUILD:-$GRANAIR_ROOT/build}"
export WM_PROJECT_DIR="${GRANAIR_OPENFOAM_SRC:-$GRANAIR_ROOT/.cache/openfoam-OpenFOAM-v1912.200626}"
export WM_PROJECT=OpenFOAM WM_PROJECT_VERSION=v1912
export FOAM_SIGFPE=true          # stop on floating-point exceptions (NaN) rather than run on
export PATH="$GRANAIR_BUILD/bin:$PATH"
# Plotting uses Debian's python3-matplotlib/numpy, which belong to /usr/bin/python3
# (another python3 earlier on PATH, e.g. pyenv's, would not see them).
if [ -z "${GRANAIR_PYTHON:-}" ]; then
  if [ -x /usr/bin/python3 ]; then GRANAIR_PYTHON=/usr/bin/python3; else GRANAIR_PYTHON=python3; fi
fi
export GRANAIR_PYTHON
# The case layer (tools/granair_cases, docs/cases.md): cases import it by name.
case ":${PYTHONPATH:-}:" in *":$GRANAIR_ROOT/tools:"*) ;; *) export PYTHONPATH="$GRANAIR_ROOT/tools${PYTHONPATH:+:$PYTHONPATH}" ;; esac
# Open MPI: allow root (CI, containers) and more ranks than cores.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
if [ ! -f "$WM_PROJECT_DIR/etc/controlDict" ]; then
  echo "granair: OpenFOAM runtime tree missing at $WM_PROJECT_DIR; run ./granair deps" >&2
  return 1 2>/dev/null || exit 1
fi
unset _granair_root
