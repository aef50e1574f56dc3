#!/usr/bin/env bash
# ----------------------------------------------------------------------
# NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
# spheropolyhedra coupled to elastic wires.
#
# Copyright (2026) the NSCD package developers. This software is
# distributed under the GNU General Public License, version 2, the
# licence of LAMMPS. See the LICENSE file in the top-level directory
# of the package.
# ----------------------------------------------------------------------
# Contributing author: the NSCD package developers
# ----------------------------------------------------------------------

# Installs what the build needs (Debian packages, LAMMPS' source), configures and builds.
# Idempotent: reuses an existing build tree (and ccache). Used by run_example.sh and
# run_tests.sh; extra arguments go to the CMake configure step.
#
#   tools/build.sh [-DLAMMPS_SOURCE_DIR=/path/to/lammps] [other -D options]
#
# Environment: BUILD_DIR (default <repo>/build), JOBS (default: number of cores).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$here/build}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

packages=(g++ cmake make xz-utils ca-certificates libopenmpi-dev openmpi-bin
          libeigen3-dev libqhull-dev libgtest-dev libgmock-dev libbenchmark-dev ccache
          pkg-config libyaml-dev                   # LAMMPS' force-style testers (tests/force-styles)
          libfftw3-dev python3-numpy python3-scipy python3-matplotlib
          python3-sphinx python3-myst-parser       # the docs test (doc/conf.py, ctest -L docs)
          paraview python3-paraview xvfb xauth)    # ParaView renders (doc/analysis.md): ~1 min, ~150 packages
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build.sh: installing Debian packages: ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "build.sh: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo=sudo
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

if [ ! -f "$build/CMakeCache.txt" ] || [ $# -gt 0 ]; then
  cmake -S "$here" -B "$build" "$@"
fi
cmake --build "$build" -j "$jobs"
