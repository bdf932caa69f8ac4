#!/usr/bin/env bash
# Builds the C# binding and runs its xunit tests against a freshly built libverve.so.
#   bindings/csharp/test.sh <folder containing libverve.so>
# Prints dotnet test's summary; exits non-zero when a build step or a test fails.
set -euo pipefail

if [[ $# -ne 1 ]]; then
    echo "usage: $0 <native-lib-dir>   (the folder holding libverve.so)" >&2
    exit 2
fi
native_dir=$(cd "$1" && pwd)
if [[ ! -f "$native_dir/libverve.so" ]]; then
    echo "error: no libverve.so in $native_dir" >&2
    exit 2
fi

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cd "$here"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1

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
# ...and the NuGet package must build, native library included.
dotnet pack Verve/Verve.csproj -c Release -p:VerveNativeDir="$native_dir" -o "$here/bin/package" -v quiet -nologo
