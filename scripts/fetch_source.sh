#!/usr/bin/env bash
# Fetches and unpacks a Debian source package into a folder, for third-party code that Debian ships
# only as source (pugixml for static and cross builds, Godot's GDNative headers).
#   ./scripts/fetch_source.sh PACKAGE DEST [PATH...]   -> DEST/PACKAGE/ (skipped when already there)
# PACKAGE may name a binary package (godot3: its source, godot); PATHs (relative to the source tree's top)
# unpack only those parts of a large tree.
# The deb-src entry and package lists live in a private apt state folder under DEST, so the machine's
# own apt configuration and lists stay untouched.
set -euo pipefail
pkg=$1
dest=$(mkdir -p "$2" && cd "$2" && pwd)
shift 2
paths=("$@")
if [ -d "$dest/$pkg" ]; then exit 0; fi

state=$dest/.apt-$pkg
mkdir -p "$state/sources.list.d" "$state/lists/partial" "$state/dl"
# The mirror is the machine's own (scripts/lib/debian_mirror.sh). For the parser's own test
# (scripts/check_fetch_source_mirror.sh): VERVE_APT_ETC names another folder to read the apt sources
# from, and VERVE_FETCH_SOURCE_PRINT_MIRROR=1 prints what was found instead of fetching.
etc=${VERVE_APT_ETC:-/etc/apt}
. "$(dirname "$0")/lib/debian_mirror.sh"
mirror=$(debian_mirror "$etc")
if [ -z "$mirror" ]; then
  echo "fetch_source.sh: no Debian mirror in this machine's apt sources (no \"deb\" entry for a release" >&2
  echo "suite in $etc/sources.list.d/*.sources or $etc/sources.list); add one and rerun." >&2
  rm -rf "$state"
  exit 1
fi
IFS='|' read -r uri suite comps signed <<<"$mirror"
if [ -n "${VERVE_FETCH_SOURCE_PRINT_MIRROR:-}" ]; then echo "$uri $suite $comps $signed"; rm -rf "$state"; exit 0; fi
{
  echo "Types: deb-src"
  echo "URIs: $uri"
  echo "Suites: $suite"
  echo "Components: ${comps:-main}"
  if [ -n "$signed" ]; then echo "Signed-By: $signed"; fi
} > "$state/sources.list.d/src.sources"
apt_opts=(-o "Dir::Etc::SourceParts=$state/sources.list.d" -o Dir::Etc::SourceList=/dev/null
  -o "Dir::State::Lists=$state/lists" -o APT::Sandbox::User=root)
apt-get "${apt_opts[@]}" update -qq
(cd "$state/dl" && apt-get "${apt_opts[@]}" source --download-only -qq "$pkg" >/dev/null)
# Unpack the upstream tarball only: the Debian patches are not needed for what we take.
tarball=$(ls "$state/dl/"*.orig.tar.* | head -n 1)
# Most tarballs hold one top folder (dropped); some (luajit's) hold the tree itself.
tops=$(tar -tf "$tarball" | sed 's#^\./##' | cut -d/ -f1 | sort -u | grep -v '^$' | wc -l)
strip=0 prefix=
if [ "$tops" -eq 1 ]; then strip=1 prefix='*/'; fi
members=()
for path in "${paths[@]}"; do members+=("$prefix$path"); done
rm -rf "$dest/$pkg.partial"; mkdir -p "$dest/$pkg.partial"
tar -xf "$tarball" -C "$dest/$pkg.partial" --strip-components=$strip --wildcards "${members[@]}"
mv "$dest/$pkg.partial" "$dest/$pkg"
rm -rf "$state"
