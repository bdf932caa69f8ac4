#!/usr/bin/env bash
# Compiles MonoHost.cs with Mono's mcs against a Verve.dll (netstandard2.1) and runs it under mono, as
# Unity's Mono runtime would load the binding.
#   bindings/csharp/mono/run.sh [--static] <Verve.dll> <folder containing libverve.so>
# By default libverve.so sits beside the assembly, where Mono resolves DllImport("verve").
# --static: for a Verve.dll built with VERVE_STATIC_LINK (DllImport("__Internal")), libverve.so is
# preloaded into the process instead, so its symbols are in the executable's global scope as they are
# when IL2CPP links the library into the game.
# Takes a few seconds; the run is cut off after 120 s. Exits non-zero when a check fails.
set -euo pipefail

static=0
if [[ ${1:-} == --static ]]; then static=1; shift; fi
if [[ $# -ne 2 || ! -f "$1" || ! -f "$2/libverve.so" ]]; then
    echo "usage: $0 [--static] <Verve.dll> <folder containing libverve.so>" >&2
    exit 2
fi
for tool in mcs mono; do
    command -v "$tool" >/dev/null || { echo "error: $tool not found (Debian package mono-devel; scripts/setup.sh --test)" >&2; exit 2; }
done
facades=/usr/lib/mono/4.5/Facades
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
native=$(realpath "$2/libverve.so")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cp "$1" "$work/"
mcs -nologo -langversion:7.2 -warnaserror -r:"$work/Verve.dll" -r:"$facades/netstandard.dll" \
    -out:"$work/MonoHost.exe" "$here/MonoHost.cs"
cd "$work"
if (( static )); then
    LD_PRELOAD="$native" timeout 120 mono --debug MonoHost.exe
else
    cp "$native" libverve.so
    env -u LD_LIBRARY_PATH timeout 120 mono --debug MonoHost.exe
fi
