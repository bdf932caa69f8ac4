#!/usr/bin/env bash
# The oldest glibc an ELF binary loads on is the highest GLIBC_x.y version among the symbols it
# imports. Fails when that is above FLOOR (default 2.31: Debian 11, Ubuntu 20.04, the Steam Linux
# Runtime 3 "sniper"), the floor docs/platforms.md promises for the shipped Linux binaries.
#   ./scripts/check_glibc_floor.sh FILE [FLOOR]   -> "FILE: glibc 2.xx (floor 2.31)", exit 1 above it
set -euo pipefail
file=$1 floor=${2:-2.31}
[ -f "$file" ] || { echo "check_glibc_floor.sh: no such file: $file" >&2; exit 2; }
dump=$(objdump -T "$file") || { echo "check_glibc_floor.sh: objdump -T failed on $file" >&2; exit 2; }
# Versions of imported (UND) symbols only: a library's own version nodes are not requirements.
need=$(awk '/\*UND\*/' <<<"$dump" | grep -o 'GLIBC_[0-9][0-9.]*' | sed 's/GLIBC_//' | sort -uV | tail -n 1)
if [ -z "$need" ]; then echo "$file: no versioned glibc symbol"; exit 0; fi
newest=$(printf '%s\n%s\n' "$need" "$floor" | sort -V | tail -n 1)
if [ "$newest" != "$floor" ]; then
  # Name every symbol above the floor: each is a reason (e.g. _dl_find_object, 2.35, from libgcc's
  # unwinder; pthread_create, 2.34, once libpthread moved into libc).
  above=$(awk '/\*UND\*/ && /\(GLIBC_/ { v = $0; sub(/.*\(GLIBC_/, "", v); sub(/\).*/, "", v); print v " " $NF }' <<<"$dump" |
    while read -r v sym; do
      [ "$(printf '%s\n%s\n' "$v" "$floor" | sort -V | tail -n 1)" = "$floor" ] || echo "$sym@GLIBC_$v"
    done | sort -u | tr '\n' ' ')
  echo "$file: needs glibc $need, above the floor $floor: $above" >&2
  exit 1
fi
echo "$file: glibc $need (floor $floor)"
