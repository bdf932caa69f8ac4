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
members=()
for path in "$@"; do members+=("*/$path"); done
if [ -d "$dest/$pkg" ]; then exit 0; fi

state=$dest/.apt-$pkg
mkdir -p "$state/sources.list.d" "$state/lists/partial" "$state/dl"
cat > "$state/sources.list.d/src.sources" <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
apt_opts=(-o "Dir::Etc::SourceParts=$state/sources.list.d" -o Dir::Etc::SourceList=/dev/null
  -o "Dir::State::Lists=$state/lists" -o APT::Sandbox::User=root)
apt-get "${apt_opts[@]}" update -qq
(cd "$state/dl" && apt-get "${apt_opts[@]}" source --download-only -qq "$pkg" >/dev/null)
# Unpack the upstream tarball only: the Debian patches are not needed for what we take.
tarball=$(ls "$state/dl/"*.orig.tar.* | head -n 1)
rm -rf "$dest/$pkg.partial"; mkdir -p "$dest/$pkg.partial"
tar -xf "$tarball" -C "$dest/$pkg.partial" --strip-components=1 --wildcards "${members[@]}"
mv "$dest/$pkg.partial" "$dest/$pkg"
rm -rf "$state"
