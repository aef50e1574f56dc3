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

# Fetch a LAMMPS source tree from Debian's `lammps` source package into a cache directory
# outside the tracked files, and print the path of the unpacked tree.
#
#   tools/fetch_lammps.sh [CACHE_DIR] [RELEASE]
#
# RELEASE  4Feb2025 (default): Debian trixie's 20250204+dfsg.1-*, pinned by its SHA-256;
#          4Jul2026: Debian sid's 20260704+dfsg-* (sid moves: this may disappear, and is then
#          refused with the versions sid offers).
# CACHE_DIR defaults to $NSCD_CACHE or ~/.cache/nscd-lammps. Idempotent: an unpacked tree is
# reused. Only the orig tarball is used (the archive may lack the .dsc, so dpkg-source is
# not needed); its SHA-256 is checked against the archive's signed index (and, for the
# default, against the pinned value). A private apt configuration leaves the system's apt
# sources as they are.
set -euo pipefail

cache=${1:-${NSCD_CACHE:-$HOME/.cache/nscd-lammps}}
release=${2:-4Feb2025}

case "$release" in
  4Feb2025) suite=trixie; version=20250204+dfsg.1
            pinned=3671165bd52fad36734e0a9136c5bc5ecb225e03988f8c89aa13366a8b53b1c7 ;;
  4Jul2026) suite=sid; version=20260704+dfsg; pinned= ;;
  *) echo "fetch_lammps: unknown release '$release' (known: 4Feb2025, 4Jul2026); for another" \
          "LAMMPS tree configure with -DLAMMPS_SOURCE_DIR=/path/to/lammps" >&2; exit 2 ;;
esac

mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
tree="$cache/lammps-$release"
if [ -f "$tree/cmake/CMakeLists.txt" ] && [ -f "$tree/src/version.h" ]; then
  echo "$tree"
  exit 0
fi

apt_dir="$cache/apt-$suite"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/archives/partial"
cat > "$apt_dir/sources.list" <<SRC
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $suite main
SRC
opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o "Dir::Etc::SourceParts=-"
      -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache::Archives=$apt_dir/archives"
      -o "APT::Sandbox::User=root")

echo "fetch_lammps: LAMMPS $release from Debian $suite's lammps $version into $cache" >&2
apt-get "${opts[@]}" -qq update >&2
offered=$(apt-cache "${opts[@]}" showsrc lammps | sed -n 's/^Version: //p' | tr '\n' ' ')
# The orig tarball's line in the signed index: "<sha256> <size> lammps_<upstream>.orig.tar.*"
upstream=${version%%-*}
index_line=$(apt-cache "${opts[@]}" showsrc "lammps" |
  awk '/^Checksums-Sha256:/ {s=1; next} /^[^ ]/ {s=0} s' |
  grep -E " lammps_${upstream//+/\\+}\.orig\.tar\.[a-z]+$" | head -n 1 || true)
if [ -z "$index_line" ]; then
  echo "fetch_lammps: Debian $suite no longer offers lammps $upstream (it offers: ${offered:-nothing});" \
       "pass a LAMMPS tree with -DLAMMPS_SOURCE_DIR=/path/to/lammps" >&2
  exit 1
fi
read -r sha size name <<<"$index_line"
full_version=$(apt-cache "${opts[@]}" showsrc lammps | sed -n "s/^Version: \(${upstream//+/\\+}-.*\)/\1/p" | head -n 1)
if [ -n "$pinned" ] && [ "$sha" != "$pinned" ]; then
  echo "fetch_lammps: the archive's SHA-256 of $name is $sha, not the pinned $pinned" >&2
  exit 1
fi

download="$cache/download-$release"
mkdir -p "$download"
if ! echo "$sha  $download/$name" | sha256sum -c --status 2>/dev/null; then
  rm -f "$download/$name"
  # Also asks for the .dsc and debian tarball, which the archive may not have: only the orig
  # tarball matters, so the exit status is not trusted; the checksum below decides. apt's
  # "404 Not Found" for the .dsc would alarm in a build log: its output is kept in a file and
  # shown only when the tarball did not come.
  echo "fetch_lammps: downloading $name (only the orig tarball is used)" >&2
  ( cd "$download" && apt-get "${opts[@]}" -qq --download-only source "lammps=$full_version" \
      >"$download/apt-source.log" 2>&1 || true )
  [ -f "$download/$name" ] ||
    { cat "$download/apt-source.log" >&2; echo "fetch_lammps: could not download $name" >&2; exit 1; }
  echo "$sha  $download/$name" | sha256sum -c --status ||
    { echo "fetch_lammps: $name does not match the archive's SHA-256 $sha" >&2; exit 1; }
fi

# The 2025 tarball holds lammps-4Feb2025/, the 2026 one cmake/, src/, ... at its top.
rm -rf "$tree.tmp"
mkdir -p "$tree.tmp"
tar -xf "$download/$name" -C "$tree.tmp"
top=$(find "$tree.tmp" -maxdepth 3 -path '*/cmake/CMakeLists.txt' | head -n 1)
top=${top%/cmake/CMakeLists.txt}
[ -f "$top/src/version.h" ] || { echo "fetch_lammps: $name holds no LAMMPS tree" >&2; exit 1; }
rm -rf "$tree"
mv "$top" "$tree"
rm -rf "$tree.tmp"
echo "$tree"
