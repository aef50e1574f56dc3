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

# The in-tree route: the package copied into a LAMMPS source tree as LAMMPS' own packages are,
# built there with -DPKG_NSCD=on, and this repository's test suite run against that build.
#
#   tools/build_intree.sh [--no-tests] [other -D options for the configure step]
#
# 1. A scratch copy of the fetched LAMMPS tree in $INTREE_DIR/lammps (the cache in
#    ~/.cache/nscd-lammps is only read; examples/, bench/ and the manual are left out).
# 2. The package installed in that copy: src/*.{h,cpp} -> src/NSCD/, lib/ -> lib/nscd/,
#    cmake/intree/NSCD.cmake -> cmake/Modules/Packages/NSCD.cmake, and NSCD added to
#    STANDARD_PACKAGES and to the packages whose module cmake/CMakeLists.txt includes.
# 3. LAMMPS' own cmake/ configured alone, as a user would, with -DPKG_NSCD=on -DPKG_MOLECULE=on
#    ($INTREE_DIR/plain, configure only, ~30 s): NSCD must be among its enabled packages and
#    its generated style headers must hold our styles.
# 4. The same tree configured with -DPKG_NSCD=on (plus MOLECULE for the wire decks and BODY for
#    the benchmarks/peer test) and built: $INTREE_DIR/build/lmp. This configure goes through
#    this repository's CMakeLists.txt with -DNSCD_INTREE_LAMMPS_DIR, which hands the tree to
#    LAMMPS' cmake/ as it is (LAMMPS compiles the package, with its own main()) and adds the
#    tests.
# 5. ctest in $INTREE_DIR/build (the whole suite; --no-tests skips it).
#
# Environment: LAMMPS_SOURCE_DIR (default: tools/fetch_lammps.sh's tree), INTREE_DIR (default
# <repo>/build-intree), JOBS (default 2).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=${INTREE_DIR:-$here/build-intree}
jobs=${JOBS:-2}
run_tests=1
if [ "${1:-}" = "--no-tests" ]; then run_tests=0; shift; fi

src_tree=${LAMMPS_SOURCE_DIR:-$(bash "$here/tools/fetch_lammps.sh")}
[ -f "$src_tree/cmake/CMakeLists.txt" ] ||
  { echo "build_intree: $src_tree is no LAMMPS tree (no cmake/CMakeLists.txt)" >&2; exit 1; }
tree=$work/lammps

copy_lammps_tree() {
  if [ -f "$tree/.nscd-copied-from" ] && [ "$(cat "$tree/.nscd-copied-from")" = "$src_tree" ]; then
    return    # kept between runs: an unchanged file keeps its time stamp and is not rebuilt
  fi
  echo "build_intree: copying $src_tree to $tree"
  rm -rf "$tree"
  mkdir -p "$tree/doc"
  tar -C "$src_tree" --exclude=./examples --exclude=./bench --exclude=./doc -cf - . | tar -C "$tree" -xf -
  cp -p "$src_tree/doc/lammps.1" "$tree/doc/"    # installed by LAMMPS' cmake/CMakeLists.txt
  printf '%s\n' "$src_tree" > "$tree/.nscd-copied-from"
}

# Mirror the .cpp and .h files of one directory into another (find options limit the depth);
# tar keeps time stamps and an unchanged file keeps its old one, so make rebuilds only what
# changed; files gone from the package are removed.
mirror() {
  local from=$1 to=$2; shift 2
  rm -rf "$to.new"
  mkdir -p "$to.new"
  (cd "$from" && find . "$@" -type f \( -name "*.cpp" -o -name "*.h" \) -print0 |
     tar --null -T - -cf -) | tar -C "$to.new" -xf -
  if [ -d "$to" ]; then
    (cd "$to.new" && find . -type f -print0) | while IFS= read -r -d '' f; do
      if cmp -s "$to.new/$f" "$to/$f"; then touch -r "$to/$f" "$to.new/$f"; fi
    done
  fi
  rm -rf "$to"
  mv "$to.new" "$to"
}

install_package() {
  mirror "$here/src" "$tree/src/NSCD" -maxdepth 1    # not src/main: in-tree, lmp is LAMMPS' own
  mirror "$here/lib" "$tree/lib/nscd"
  cp -p "$here/cmake/intree/NSCD.cmake" "$tree/cmake/Modules/Packages/NSCD.cmake"
  register_package "$tree/cmake/CMakeLists.txt"
}

# NSCD in LAMMPS' package list (alphabetical, after NETCDF) and among the packages whose
# cmake/Modules/Packages/<name>.cmake is included before the style headers are generated.
register_package() {
  local lists=$1
  if ! grep -qx "  NSCD" "$lists"; then
    grep -qx "  NETCDF" "$lists" ||
      { echo "build_intree: no '  NETCDF' line in $lists: STANDARD_PACKAGES changed" >&2; exit 1; }
    sed -i 's/^  NETCDF$/  NETCDF\n  NSCD/' "$lists"
  fi
  if ! grep -q "^foreach(PKG_WITH_INCL KSPACE NSCD " "$lists"; then
    grep -q "^foreach(PKG_WITH_INCL KSPACE " "$lists" ||
      { echo "build_intree: no 'foreach(PKG_WITH_INCL KSPACE' in $lists" >&2; exit 1; }
    sed -i 's/^foreach(PKG_WITH_INCL KSPACE /foreach(PKG_WITH_INCL KSPACE NSCD /' "$lists"
  fi
}

# LAMMPS' cmake/ alone, as a user configures it: is the package registered?
check_plain_configure() {
  local plain=$work/plain
  rm -rf "$plain"
  cmake -S "$tree/cmake" -B "$plain" -DPKG_NSCD=on -DPKG_MOLECULE=on -DBUILD_MPI=on \
        -DWITH_JPEG=off -DWITH_PNG=off -DWITH_FFMPEG=off > "$plain.log" 2>&1 ||
    { tail -20 "$plain.log"; echo "build_intree: LAMMPS' cmake/ failed with -DPKG_NSCD=on" >&2; exit 1; }
  grep -A3 "^-- Enabled packages:" "$plain.log" | grep -qw NSCD ||
    { echo "build_intree: NSCD is not among the enabled packages ($plain.log)" >&2; exit 1; }
  grep -q "fix_nscd.h" "$plain/styles/style_fix.h" ||
    { echo "build_intree: $plain/styles/style_fix.h lacks fix_nscd.h" >&2; exit 1; }
  echo "build_intree: LAMMPS' cmake/ configures with -DPKG_NSCD=on (log: $plain.log)"
}

copy_lammps_tree
install_package
check_plain_configure
cmake -S "$here" -B "$work/build" -DNSCD_INTREE_LAMMPS_DIR="$tree" -DPKG_NSCD=on \
      -DPKG_MOLECULE=on -DPKG_BODY=on -DPKG_GRANULAR=off "$@"
cmake --build "$work/build" -j "$jobs"
"$work/build/lmp" -h | grep -A3 "^Installed packages:" | grep -qw NSCD ||
  { echo "build_intree: $work/build/lmp does not list NSCD among its installed packages" >&2; exit 1; }
echo "build_intree: $work/build/lmp built in-tree with the NSCD package"
if [ $run_tests -eq 1 ]; then
  ctest --test-dir "$work/build" -j "$jobs" --output-on-failure
fi
