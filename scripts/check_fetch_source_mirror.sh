#!/usr/bin/env bash
# scripts/fetch_source.sh takes its Debian mirror from the machine's apt sources: checks that it reads
# the deb822 form (/etc/apt/sources.list.d/*.sources) and the one-line form (/etc/apt/sources.list),
# skips -updates/-security suites and deb-src entries, and stops with a clear error when there is no
# "deb" entry. Runs on fake apt folders (VERVE_APT_ETC) with local file: URIs (no host): nothing is
# downloaded. Run by scripts/test.sh after check_no_hosts.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect NAME WANT: fetch_source.sh, reading $work/NAME, prints WANT (uri suite components signed-by).
expect() {
  local got
  got=$(VERVE_FETCH_SOURCE_PRINT_MIRROR=1 VERVE_APT_ETC="$work/$1" ./scripts/fetch_source.sh none "$work/dest" 2>&1) || true
  if [ "$got" != "$2" ]; then
    echo "check_fetch_source_mirror: $1: got '$got', want '$2'" >&2
    failures=$((failures + 1))
  fi
}

mkdir -p "$work/deb822/sources.list.d"
cat > "$work/deb822/sources.list.d/debian.sources" <<'SRC'
Types: deb-src
URIs: file:/srv/source-only/debian
Suites: bookworm
Components: main

Types: deb
# a comment between fields
URIs: file:/srv/security/debian-security
Suites: bookworm-security
Components: main

Types: deb
URIs: file:/srv/mirror/debian
Suites: bookworm-updates bookworm
Components: main contrib
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
expect deb822 "file:/srv/mirror/debian bookworm main contrib /usr/share/keyrings/debian-archive-keyring.gpg"

mkdir -p "$work/one-line/sources.list.d"
cat > "$work/one-line/sources.list" <<'SRC'
# deb file:/srv/commented/debian bookworm main
deb-src file:/srv/source-only/debian bookworm main
deb [arch=amd64 signed-by=/etc/apt/keyrings/k.gpg] file:/srv/mirror/debian bookworm-updates main
deb [arch=amd64 signed-by=/etc/apt/keyrings/k.gpg] file:/srv/mirror/debian bookworm main non-free
SRC
expect one-line "file:/srv/mirror/debian bookworm main non-free /etc/apt/keyrings/k.gpg"

mkdir -p "$work/none/sources.list.d"
echo "deb file:/srv/security/debian-security bookworm-security main" > "$work/none/sources.list"
expect none "fetch_source.sh: no Debian mirror in this machine's apt sources (no \"deb\" entry for a release
suite in $work/none/sources.list.d/*.sources or $work/none/sources.list); add one and rerun."
if [ -e "$work/dest/.apt-none" ]; then
  echo "check_fetch_source_mirror: the failed run left its apt state behind" >&2
  failures=$((failures + 1))
fi

if [ "$failures" -ne 0 ]; then exit 1; fi
echo "check_fetch_source_mirror: deb822 and one-line apt sources read, no mirror refused clearly"
