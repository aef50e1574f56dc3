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

# Configures the project once more, with LAMMPS' KSPACE package on, in a scratch build tree
# and checks that LAMMPS takes FFTW3 as its FFT library (not its KISS fallback).
#   kspace_uses_fftw3.sh SOURCE_DIR LAMMPS_TREE SCRATCH_DIR
set -euo pipefail
src=$1; tree=$2; work=$3
rm -rf "$work"
cmake -S "$src" -B "$work" -DLAMMPS_SOURCE_DIR="$tree" -DPKG_KSPACE=on \
      -DNSCD_BUILD_TESTS=OFF -DNSCD_BUILD_BENCHMARKS=OFF > "$work.log" 2>&1 ||
  { tail -20 "$work.log"; exit 1; }
grep -q "^FFT:STRING=FFTW3$" "$work/CMakeCache.txt" ||
  { echo "FFT is not FFTW3:"; grep "^FFT:" "$work/CMakeCache.txt"; exit 1; }
grep -Eq "Primary FFT lib: +FFTW3" "$work.log" ||
  { echo "LAMMPS did not report FFTW3:"; grep -A2 "FFT settings" "$work.log"; exit 1; }
grep -Eq "FFTW3_LIBRARY:FILEPATH=.*fftw3" "$work/CMakeCache.txt" ||
  { echo "no FFTW3 library found"; exit 1; }
rm -rf "$work" "$work.log"
echo "KSPACE configures with FFTW3"
