#!/usr/bin/env bash
# Installs what frix needs from Debian's packages (if missing) and builds it with CMake.
#   scripts/setup.sh [--petsc] [BUILD_DIR [BUILD_TYPE]]   (defaults: build, Release)
# --petsc also installs Debian's PETSc (petsc-dev, with OpenMPI and MUMPS) and configures
# with FRIX_PETSC=ON (SOLVER Petsc, docs/solver.md). FRIX_BUILD_TARGET (environment) builds
# that target only (e.g. frix) instead of everything.
# BUILD_TYPE may also come from the environment variable FRIX_BUILD_TYPE (the argument wins):
# Release, Debug, or Sanitize (ASan + UBSan, see scripts/check.sh).
# Used by both README commands and by CI. Safe to run again: it only installs what is missing
# and rebuilds incrementally.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
petsc=OFF
if [ "${1:-}" = --petsc ]; then petsc=ON; shift; fi
build_dir=${1:-$root/build}
build_type=${2:-${FRIX_BUILD_TYPE:-Release}}

packages=(gfortran gcc cmake make libsuitesparse-dev libmetis-dev libhdf5-dev gmsh numdiff
          libopenblas0-pthread python3-numpy python3-matplotlib python3-meshio python3-h5py
          time)   # GNU time: the bench scripts (bench/) read CPU times from it
[ "$petsc" = ON ] && packages+=(petsc-dev pkg-config)
# The Sanitize build's runtimes (libasan8, libubsan1) come with gcc: gfortran -> gcc-12 ->
# libgcc-12-dev, which depends on both (Debian 12).

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  install() {
    "${sudo_cmd[@]}" apt-get update -q &&
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q "${missing[@]}"
  }
  # apt can fail once when another apt run cleans its cache at the wrong moment: retry once.
  if ! install; then
    echo "setup: apt-get failed, retrying once in 10 s"
    sleep 10
    install
  fi
fi

cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type" -DFRIX_PETSC="$petsc" > "$build_dir.configure.log" 2>&1 ||
  { cat "$build_dir.configure.log"; exit 1; }
cmake --build "$build_dir" -j"$(nproc)" ${FRIX_BUILD_TARGET:+--target "$FRIX_BUILD_TARGET"}
