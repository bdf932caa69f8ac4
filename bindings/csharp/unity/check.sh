#!/usr/bin/env bash
# Checks a Unity package made by make_package.sh without Unity (none is installed here):
#   bindings/csharp/unity/check.sh <package folder> <folder with libverve.so> [<folder with verve.dll>]
# - the layout: package.json, README.md, LICENSE.md, THIRD_PARTY_NOTICES.md, Runtime/Verve.asmdef with every source of the binding,
#   the native library of each platform given (byte for byte, and no Windows one when none is given);
# - package.json and the .asmdef are valid JSON with the right name, version and unsafe code allowed;
# - every file and folder has a .meta, every .meta its file, all GUIDs distinct;
# - each native library's import settings enable exactly its OS's editor and x86_64 player;
# - Runtime/ compiles as Unity compiles it (Roslyn, C# 9, against the netstandard2.1 reference, only the
#   asmdef's settings), and that assembly passes the Mono host (mono/run.sh) with the packaged libverve.so;
#   so does the VERVE_STATIC_LINK variant, with libverve preloaded (mono/run.sh --static).
# Takes about 20 s. Exits non-zero on the first failed check.
set -euo pipefail

if [[ $# -lt 2 || $# -gt 3 || ! -f "$1/package.json" ]]; then
    echo "usage: $0 <package folder> <folder with libverve.so> [<folder with verve.dll>]" >&2
    exit 2
fi
pkg=$(cd "$1" && pwd)
linux_lib=$2/libverve.so
windows_lib=${3:+$3/verve.dll}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
binding="$here/../Verve"
fail() { echo "unity check: $*" >&2; exit 1; }

# Layout.
for f in package.json Runtime/Verve.asmdef; do [[ -f $pkg/$f ]] || fail "no $f"; done
repo="$here/../../.."
for pair in docs/csharp.md:README.md LICENSE:LICENSE.md THIRD_PARTY_NOTICES.md:THIRD_PARTY_NOTICES.md; do
    cmp -s "$repo/${pair%%:*}" "$pkg/${pair#*:}" || fail "${pair#*:} is missing or differs from the repository's ${pair%%:*}"
done
expected_sources=$(cd "$binding" && find . -name '*.cs' -not -path './obj/*' -not -path './bin/*' | sort)
packaged_sources=$(cd "$pkg/Runtime" && find . -name '*.cs' | sort)
[[ $expected_sources == "$packaged_sources" ]] || fail "Runtime/ does not hold exactly the binding's sources"
cmp -s "$linux_lib" "$pkg/Plugins/Linux/x86_64/libverve.so" || fail "Plugins/Linux/x86_64/libverve.so is missing or differs from $linux_lib"
if [[ -n $windows_lib ]]; then
    cmp -s "$windows_lib" "$pkg/Plugins/Windows/x86_64/verve.dll" || fail "Plugins/Windows/x86_64/verve.dll is missing or differs from $windows_lib"
elif [[ -e $pkg/Plugins/Windows ]]; then
    fail "the package has a Windows library, but none was given to check it against"
fi

# JSON.
version=$(sed -n 's:.*<Version>\(.*\)</Version>.*:\1:p' "$binding/Verve.csproj")
jq -e --arg v "$version" '.name == "com.verve.agent" and .version == $v and .unity == "2021.2" and .license == "MIT"' \
    "$pkg/package.json" >/dev/null || fail "package.json is not valid JSON or has the wrong name, version, unity or license"
jq -e '.name == "Verve.Net" and .allowUnsafeCode == true and .noEngineReferences == true' \
    "$pkg/Runtime/Verve.asmdef" >/dev/null || fail "Runtime/Verve.asmdef is not valid JSON or lacks name Verve.Net / allowUnsafeCode"

# .meta files: one per asset, distinct GUIDs.
while read -r path; do
    [[ -f $pkg/$path.meta ]] || fail "no .meta for $path"
done < <(cd "$pkg" && find . -mindepth 1 -not -name '*.meta' | sed 's:^\./::')
while read -r meta; do
    [[ -e $pkg/${meta%.meta} ]] || fail "$meta has no asset"
    grep -Eq '^guid: [0-9a-f]{32}$' "$pkg/$meta" || fail "$meta has no GUID"
done < <(cd "$pkg" && find . -name '*.meta' | sed 's:^\./::')
duplicates=$(cat $(find "$pkg" -name '*.meta') | sed -n 's/^guid: //p' | sort | uniq -d)
[[ -z $duplicates ]] || fail "GUIDs used twice: $duplicates"

# Import settings: "<platform> enabled=<0|1> CPU=<cpu> OS=<os>" per platformData entry.
platforms() {
    awk '/^  - first:/ { if (p != "") print p, e, c, o; getline; sub(/^ +/, ""); p = $0; e = c = o = "" }
         /^      enabled:/ { e = "enabled=" $2 }
         /^        CPU:/ { c = "CPU=" $2 }
         /^        OS:/ { o = "OS=" $2 }
         /^  userData:/ { print p, e, c, o }' "$1" | tr -s ' ' | sed 's/ $//'
}
expect_platforms() {  # <meta> <Linux|Windows>
    local linux=0 win=0 lcpu=None wcpu=None
    if [[ $2 == Linux ]]; then linux=1 lcpu=x86_64; else win=1 wcpu=x86_64; fi
    printf '%s\n' ": Any enabled=0" "Any: enabled=0" "Editor: Editor enabled=1 CPU=x86_64 OS=$2" \
        "Standalone: Linux64 enabled=$linux CPU=$lcpu" "Standalone: OSXUniversal enabled=0 CPU=None" \
        "Standalone: Win enabled=0 CPU=None" "Standalone: Win64 enabled=$win CPU=$wcpu"
}
for plugin in Linux/x86_64/libverve.so Windows/x86_64/verve.dll; do
    meta="$pkg/Plugins/$plugin.meta"
    [[ -f $meta ]] || continue
    os=${plugin%%/*}
    grep -q '^PluginImporter:' "$meta" || fail "Plugins/$plugin.meta is not a PluginImporter"
    diff <(expect_platforms "$meta" "$os") <(platforms "$meta") >&2 ||
        fail "Plugins/$plugin.meta does not enable exactly the $os editor and x86_64 player (expected < actual)"
    grep -q "^        Exclude $( [[ $os == Linux ]] && echo Linux64 || echo Win64 ): 0$" "$meta" ||
        fail "Plugins/$plugin.meta excludes its own player"
done
echo "unity check: layout, JSON, .meta files and import settings of $(basename "$pkg") $version"

# Runtime/ compiled as Unity does (no csproj: C# 9, unsafe from the asmdef, netstandard2.1 reference).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sdk=$(dotnet --list-sdks | tail -1 | sed 's/^\([^ ]*\) \[\(.*\)\]$/\2\/\1/')
netstandard=$(dotnet nuget locals global-packages --list | sed 's/^global-packages: //')netstandard.library.ref/2.1.0/ref/netstandard2.1/netstandard.dll
[[ -f $netstandard ]] || fail "no netstandard2.1 reference assembly at $netstandard (restore bindings/csharp/Verve first)"
mapfile -t sources < <(find "$pkg/Runtime" -name '*.cs' | sort)
# Twice: as is, and with the VERVE_STATIC_LINK scripting define that iOS/WebGL builds set, run with
# libverve preloaded into the process (DllImport("__Internal")).
for variant in dynamic static; do
    define=()
    [[ $variant == dynamic ]] || define=(-define:VERVE_STATIC_LINK)
    mkdir -p "$work/$variant"
    dotnet "$sdk/Roslyn/bincore/csc.dll" -nologo -noconfig -nostdlib -target:library -langversion:9 -unsafe \
        -warnaserror "${define[@]}" -r:"$netstandard" -out:"$work/$variant/Verve.Net.dll" "${sources[@]}" ||
        fail "Runtime/ does not compile on its own (C# 9, netstandard2.1, $variant)"
    mono_args=("$work/$variant/Verve.Net.dll" "$pkg/Plugins/Linux/x86_64")
    [[ $variant == dynamic ]] || mono_args=(--static "${mono_args[@]}")
    mono_log=$("$here/../mono/run.sh" "${mono_args[@]}" 2>&1) ||
        { echo "$mono_log" >&2; fail "the assembly compiled from Runtime/ ($variant) fails under Mono"; }
    echo "$variant: $(tail -1 <<<"$mono_log")"
done
echo "unity check: ok"
