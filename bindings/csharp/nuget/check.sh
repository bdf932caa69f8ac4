#!/usr/bin/env bash
# Checks a Verve NuGet package as its users get it:
#   bindings/csharp/nuget/check.sh <Verve.nupkg> <folder with libverve.so> [<folder with verve.dll>]
# - the license expression (MIT), the readme, the third-party notices, the assembly, and the native library of each runtime
#   given, byte for byte (and no win-x64 library when no verve.dll folder is given);
# - a console project referencing the package (restored from it alone, into a private package cache)
#   builds and runs on Linux, loading libverve.so from the package's runtimes/linux-x64/native/;
# - its build output lists runtimes/win-x64/native/verve.dll for the win-x64 RID, and a win-x64
#   publish puts verve.dll beside the app: how .NET finds DllImport("verve") on Windows (Windows itself
#   is not run here).
# Takes about 30 s, 60 s with win-x64 (restore, build, run, publish). Exits non-zero on the first failed check.
set -euo pipefail

if [[ $# -lt 2 || $# -gt 3 || ! -f "$1" ]]; then
    echo "usage: $0 <Verve.nupkg> <folder with libverve.so> [<folder with verve.dll>]" >&2
    exit 2
fi
nupkg=$(realpath "$1")
linux_lib=$(realpath "$2")/libverve.so
windows_lib=${3:+$(realpath "$3")/verve.dll}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "nuget check: $*" >&2; exit 1; }

unzip -q "$nupkg" -d "$work/unpacked"
nuspec="$work/unpacked/Verve.nuspec"
[[ -f $nuspec ]] || fail "no Verve.nuspec in $nupkg"
grep -q '<license type="expression">MIT</license>' "$nuspec" || fail "the nuspec has no MIT license expression"
grep -q '<readme>README.md</readme>' "$nuspec" || fail "the nuspec names no README.md"
cmp -s "$here/../../../docs/csharp.md" "$work/unpacked/README.md" || fail "README.md is missing or is not docs/csharp.md"
cmp -s "$here/../../../THIRD_PARTY_NOTICES.md" "$work/unpacked/THIRD_PARTY_NOTICES.md" ||
    fail "THIRD_PARTY_NOTICES.md is missing or differs from the repository's"
[[ -f $work/unpacked/lib/netstandard2.1/Verve.Net.dll ]] || fail "no lib/netstandard2.1/Verve.Net.dll"
cmp -s "$linux_lib" "$work/unpacked/runtimes/linux-x64/native/libverve.so" ||
    fail "runtimes/linux-x64/native/libverve.so is missing or differs from $linux_lib"
if [[ -n $windows_lib ]]; then
    cmp -s "$windows_lib" "$work/unpacked/runtimes/win-x64/native/verve.dll" ||
        fail "runtimes/win-x64/native/verve.dll is missing or differs from $windows_lib"
elif [[ -e $work/unpacked/runtimes/win-x64 ]]; then
    fail "the package has a win-x64 library, but none was given to check it against"
fi
version=$(sed -n 's:.*<version>\(.*\)</version>.*:\1:p' "$nuspec")
echo "nuget check: Verve $version: license MIT, README.md, THIRD_PARTY_NOTICES.md, Verve.Net.dll, linux-x64${windows_lib:+ and win-x64} native libraries"

# The consumer restores from the package's folder only, into a private cache (a stale copy of the same
# version in ~/.nuget/packages would hide a broken package).
cp -r "$here/Consumer" "$work/consumer"
cat >"$work/consumer/nuget.config" <<CONFIG
<configuration>
  <packageSources><clear /><add key="verve" value="$(dirname "$nupkg")" /></packageSources>
  <config><add key="globalPackagesFolder" value="$work/packages" /></config>
</configuration>
CONFIG
cd "$work/consumer"
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
dotnet build -c Release -p:VervePackageVersion="$version" -v quiet -nologo >"$work/build.log" 2>&1 ||
    { cat "$work/build.log" >&2; fail "the consumer project did not build"; }
out=$(ls -d "$work"/consumer/bin/Release/net*/)
run_log=$(env -u LD_LIBRARY_PATH dotnet "$out/Consumer.dll") || { echo "$run_log" >&2; fail "the consumer failed"; }
echo "$run_log"
grep -qx "loaded from ${out}runtimes/linux-x64/native/libverve.so" <<<"$run_log" ||
    fail "libverve.so was not loaded from the package's runtimes/linux-x64/native/"
if [[ -n $windows_lib ]]; then
    cmp -s "$windows_lib" "${out}runtimes/win-x64/native/verve.dll" || fail "the build output has no runtimes/win-x64/native/verve.dll"
    grep -q '"runtimes/win-x64/native/verve.dll": {' "$out/Consumer.deps.json" &&
        grep -A2 '"runtimes/win-x64/native/verve.dll": {' "$out/Consumer.deps.json" | grep -q '"rid": "win-x64"' ||
        fail "Consumer.deps.json does not map runtimes/win-x64/native/verve.dll to the win-x64 RID"
    # A Windows publish puts verve.dll beside the app, where Windows' DllImport("verve") looks first; it
    # fails (NETSDK1152) if any packaged file has verve.dll's name in another case (Windows ignores case).
    dotnet publish -c Release -r win-x64 --self-contained false -p:UseAppHost=false -p:VervePackageVersion="$version" \
        -o "$work/publish-win-x64" -v quiet -nologo >"$work/publish.log" 2>&1 ||
        { cat "$work/publish.log" >&2; fail "dotnet publish -r win-x64 failed"; }
    cmp -s "$windows_lib" "$work/publish-win-x64/verve.dll" || fail "the win-x64 publish has no verve.dll beside the app"
    echo "nuget check: a win-x64 publish has verve.dll beside Consumer.dll (not run: no Windows here)"
fi
echo "nuget check: ok"
