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
  users=$(awk '/\*UND\*/' <<<"$dump" | grep "GLIBC_$need " | awk '{print $NF}' | sort -u | tr '\n' ' ')
  echo "$file: needs glibc $need, above the floor $floor (symbols: $users)" >&2
  exit 1
fi
echo "$file: glibc $need (floor $floor)"
