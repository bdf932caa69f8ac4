#!/usr/bin/env bash
# Builds the C# binding and checks it against a freshly built libverve:
#   bindings/csharp/test.sh <folder containing libverve.so> [<folder containing verve.dll>]
# xunit tests (dotnet test), the sample, the NuGet package (both runtimes when verve.dll's folder is
# given), the packed assembly under Mono 6.8 (Unity's runtime), and the Unity package (layout, import
# settings, its sources compiled alone, also with VERVE_STATIC_LINK, and run under Mono).
# Exits non-zero when a build step or a check fails.
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
    echo "usage: $0 <native-lib-dir> [<windows-native-lib-dir>]   (folders holding libverve.so and verve.dll)" >&2
    exit 2
fi
native_dir=$(cd "$1" && pwd)
if [[ ! -f "$native_dir/libverve.so" ]]; then
    echo "error: no libverve.so in $native_dir" >&2
    exit 2
fi
windows_dir=
windows_args=()
if [[ $# -eq 2 ]]; then
    windows_dir=$(cd "$2" && pwd)
    windows_args=(-p:VerveWindowsNativeDir="$windows_dir")
fi

for tool in dotnet mcs mono ikdasm unzip jq; do
    command -v "$tool" >/dev/null ||
        { echo "error: $tool not found (./scripts/setup.sh --test installs mono-devel, unzip and jq)" >&2; exit 2; }
done

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cd "$here"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

dotnet test Verve.Tests/Verve.Tests.csproj -c Release -p:VerveNativeDir="$native_dir" \
    --logger "console;verbosity=minimal"
# The sample must keep working (it exits non-zero if a loaded copy acts unlike the original)...
dotnet build Verve.Sample/Verve.Sample.csproj -c Release -p:VerveNativeDir="$native_dir" -v quiet -nologo
if ! sample_log=$(dotnet run --project Verve.Sample -c Release --no-build -- 60 1 2>&1); then
    echo "$sample_log" >&2
    echo "error: Verve.Sample failed" >&2
    exit 1
fi
echo "Verve.Sample: ok"

echo "== NuGet package"
rm -rf "$here/bin/package"
dotnet pack Verve/Verve.csproj -c Release -p:VerveNativeDir="$native_dir" "${windows_args[@]}" \
    -o "$here/bin/package" -v quiet -nologo
nupkg=$(ls "$here"/bin/package/Verve.*.nupkg)
nuget/check.sh "$nupkg" "$native_dir" $windows_dir

echo "== the packed Verve.Net.dll under Mono"
unzip -q "$nupkg" 'lib/*' 'runtimes/linux-x64/*' -d "$work/package"
mono/run.sh "$work/package/lib/netstandard2.1/Verve.Net.dll" "$work/package/runtimes/linux-x64/native"

echo "== Unity package"
unity/make_package.sh "$work/unity" "$native_dir" $windows_dir >/dev/null
unity/check.sh "$work/unity/com.verve.agent" "$native_dir" $windows_dir
