#!/usr/bin/env bash
# Compiles MonoHost.cs with Mono's mcs against Verve.Net.dll (the binding, netstandard2.1) and runs it under mono, as
# Unity's Mono runtime would load the binding.
#   bindings/csharp/mono/run.sh [--static] <Verve.Net.dll> <folder containing libverve.so>
# By default libverve.so sits beside the assembly, where Mono resolves DllImport("verve").
# --static: for a Verve.Net.dll built with VERVE_STATIC_LINK (DllImport("__Internal")), libverve.so is
# preloaded into the process instead, so its symbols are in the executable's global scope as they are
# when IL2CPP links the library into the game.
# Takes a few seconds; the run is cut off after 120 s. Exits non-zero when a check fails.
set -euo pipefail

static=0
if [[ ${1:-} == --static ]]; then static=1; shift; fi
if [[ $# -ne 2 || ! -f "$1" || ! -f "$2/libverve.so" ]]; then
    echo "usage: $0 [--static] <Verve.Net.dll> <folder containing libverve.so>" >&2
    exit 2
fi
for tool in mcs mono ikdasm; do
    command -v "$tool" >/dev/null || { echo "error: $tool not found (Debian package mono-devel; scripts/setup.sh --test)" >&2; exit 2; }
done
facades=/usr/lib/mono/4.5/Facades
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
native=$(realpath "$2/libverve.so")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cp "$1" "$work/"
# Static half, for paths the host may not reach: a call to a netstandard member returning `ref readonly`
# (modreq InAttribute: a ReadOnlySpan's GetPinnableReference, indexer or enumerator) cannot bind on
# Mono 6.8, whose corlib returns plain refs there.
ikdasm "$work/Verve.Net.dll" >"$work/Verve.il"
if grep -E '(call|newobj|ldftn).*modreq\(\[netstandard\]System\.Runtime\.InteropServices\.InAttribute\).* \[netstandard\]' "$work/Verve.il" >&2; then
    echo "error: Verve.Net.dll calls the netstandard members above, missing on Mono: pin spans with" \
         "MemoryMarshal.GetReference and do not index ReadOnlySpans (see Agent.Update)" >&2
    exit 1
fi
mcs -nologo -langversion:7.2 -warnaserror -r:"$work/Verve.Net.dll" -r:"$facades/netstandard.dll" \
    -out:"$work/MonoHost.exe" "$here/MonoHost.cs"
cd "$work"
if (( static )); then
    LD_PRELOAD="$native" timeout 120 mono --debug MonoHost.exe
else
    cp "$native" libverve.so
    env -u LD_LIBRARY_PATH timeout 120 mono --debug MonoHost.exe
fi
