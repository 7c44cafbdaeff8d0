#!/usr/bin/env bash
# install-deps.sh: install everything granair needs on Debian 12, idempotently.
#
#  1. Debian packages (OpenFOAM v1912 runtime, LIGGGHTS 3.8.0, Open MPI, Eigen,
#     HDF5, Catch2, CMake, plotting).
#  2. OpenFOAM v1912 *headers*: Debian ships the libraries but no headers, so we
#     unpack Debian's own source package (the exact matching tree) into
#     .cache/openfoam-src and generate the lnInclude trees the compiler needs.
#
# Safe to rerun: each step checks first and does nothing when already done.
# Exit codes: 0 ok, 1 failure, 2 environment not supported (not Debian 12,
# not root and no sudo).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache="${GRANAIR_CACHE:-$here/.cache}"
foam_version=1912.200626
foam_tree="$cache/openfoam-OpenFOAM-v$foam_version"

say() { printf '[granair deps] %s\n' "$*"; }
die() { printf '[granair deps] ERROR: %s\n' "$*" >&2; exit "${2:-1}"; }

packages=(openfoam libopenfoam liggghts libliggghts-dev
          libopenmpi-dev openmpi-bin libeigen3-dev libhdf5-openmpi-dev catch2
          cmake g++ make bzip2 dpkg-dev
          python3-matplotlib python3-numpy python3-h5py)

# --- system check ---------------------------------------------------------
if [ -r /etc/os-release ]; then
  . /etc/os-release
  if [ "${ID:-}" != debian ] || [ "${VERSION_ID:-}" != 12 ]; then
    die "granair's installer supports Debian 12 (bookworm); this is '${PRETTY_NAME:-unknown}'. Install the packages listed in docs/install.md by hand, then set GRANAIR_OPENFOAM_SRC to an OpenFOAM v1912 source tree with lnInclude directories." 2
  fi
else
  die "cannot read /etc/os-release; granair's installer supports Debian 12 only" 2
fi

SUDO=""
if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    SUDO="sudo"
  fi
fi
need_root() {
  [ "$(id -u)" = 0 ] || [ -n "$SUDO" ] || \
    die "installing Debian packages needs root: rerun as root or give this user password-less sudo (missing: $*)" 2
}
export DEBIAN_FRONTEND=noninteractive

# --- 1. Debian packages ---------------------------------------------------
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  need_root "${missing[*]}"
  say "installing ${#missing[@]} Debian packages: ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null \
    || die "apt-get install failed for: ${missing[*]}"
else
  say "Debian packages: all present"
fi

# --- 2. OpenFOAM headers --------------------------------------------------
stamp="$foam_tree/.granair-lninclude-done"
if [ ! -f "$stamp" ]; then
  mkdir -p "$cache"
  tarball="$cache/openfoam_$foam_version.orig.tar.bz2"
  if [ ! -f "$tarball" ]; then
    srclist=/etc/apt/sources.list.d/granair-debian-src.sources
    if ! apt-get indextargets 2>/dev/null | grep -q 'Created-By: Sources'; then
      need_root "deb-src entries"
      if [ -f /etc/apt/sources.list.d/debian.sources ]; then
        sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources \
          | $SUDO tee "$srclist" >/dev/null
      elif [ -f /etc/apt/sources.list ]; then
        sed -n 's/^deb /deb-src /p' /etc/apt/sources.list \
          | $SUDO tee /etc/apt/sources.list.d/granair-debian-src.list >/dev/null
      fi
      $SUDO apt-get update -qq
    fi
    say "downloading Debian's OpenFOAM v1912 source package (headers only are used)"
    (cd "$cache" && apt-get source --download-only -qq openfoam >/dev/null) \
      || die "apt-get source openfoam failed (are deb-src entries reachable?)"
    [ -f "$tarball" ] || die "expected $tarball after apt-get source"
  fi
  say "unpacking OpenFOAM source tree into $foam_tree"
  rm -rf "$foam_tree"
  tar -C "$cache" -xjf "$tarball"
  say "generating lnInclude trees"
  export WM_PROJECT_DIR="$foam_tree"
  for l in OpenFOAM finiteVolume meshTools OSspecific/POSIX lagrangian/basic \
           transportModels/incompressible TurbulenceModels/turbulenceModels \
           TurbulenceModels/incompressible; do
    if [ -d "$foam_tree/src/$l" ]; then
      (cd "$foam_tree" && wmake/wmakeLnInclude -u "src/$l" >/dev/null) \
        || die "wmakeLnInclude failed for src/$l"
    fi
  done
  touch "$stamp"
else
  say "OpenFOAM headers: present in $foam_tree"
fi
say "done (OpenFOAM tree: $foam_tree)"
