#!/usr/bin/env bash
# Fetch the LAMMPS source tree this project builds against, from Debian's `lammps`
# source package (bookworm), into a cache directory outside the tracked files.
#
#   tools/fetch_lammps.sh [CACHE_DIR]      prints the path of the unpacked tree
#
# CACHE_DIR defaults to $NSCD_CACHE or <repo>/.cache. Idempotent: an unpacked tree
# is reused. Uses a private apt configuration, so the system's sources stay as they are.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${1:-${NSCD_CACHE:-$here/.cache}}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

existing=$(ls -d "$cache"/lammps-src/lammps-*/cmake 2>/dev/null | head -n 1 || true)
if [ -n "$existing" ]; then
  dirname "$existing"
  exit 0
fi

command -v dpkg-source >/dev/null || {
  echo "fetch_lammps: dpkg-source missing; install dpkg-dev (apt-get install dpkg-dev)" >&2; exit 1; }

apt_dir="$cache/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/archives/partial"
cat > "$apt_dir/sources.list" <<SRC
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main
SRC
opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o "Dir::Etc::SourceParts=-"
      -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache::Archives=$apt_dir/archives"
      -o "APT::Sandbox::User=root")

echo "fetch_lammps: downloading Debian's lammps source package into $cache" >&2
apt-get "${opts[@]}" -qq update >&2
rm -rf "$cache/lammps-src.tmp"
mkdir -p "$cache/lammps-src.tmp"
( cd "$cache/lammps-src.tmp" && apt-get "${opts[@]}" -qq source lammps >&2 )
tree=$(ls -d "$cache"/lammps-src.tmp/lammps-*/cmake | head -n 1)
[ -n "$tree" ] || { echo "fetch_lammps: unpacked source has no cmake/ directory" >&2; exit 1; }
rm -rf "$cache/lammps-src"
mv "$cache/lammps-src.tmp" "$cache/lammps-src"
dirname "$(ls -d "$cache"/lammps-src/lammps-*/cmake | head -n 1)"
