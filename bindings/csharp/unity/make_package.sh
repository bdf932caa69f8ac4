#!/usr/bin/env bash
# Makes the Unity package (UPM) of the C# binding:
#   bindings/csharp/unity/make_package.sh <out-dir> <folder with libverve.so> [<folder with verve.dll>]
# writes <out-dir>/com.verve.agent/ (for "Add package from disk") and
# <out-dir>/com.verve.agent-<version>.tgz (for "Add package from tarball"):
#   package.json, README.md (docs/csharp.md), LICENSE.md, THIRD_PARTY_NOTICES.md (what the libraries contain)
#   Runtime/Verve.asmdef + the binding's sources (Unity compiles them; VERVE_STATIC_LINK can be defined)
#   Plugins/Linux/x86_64/libverve.so    imported for the Linux editor and Linux x86_64 players
#   Plugins/Windows/x86_64/verve.dll    imported for the Windows editor and Windows x86_64 players
# Every file and folder gets a .meta (Unity ignores files without one in an immutable package), with a
# GUID derived from its path so it stays the same from build to build.
set -euo pipefail

if [[ $# -lt 2 || $# -gt 3 || ! -f "$2/libverve.so" || ( $# -eq 3 && ! -f "$3/verve.dll" ) ]]; then
    echo "usage: $0 <out-dir> <folder with libverve.so> [<folder with verve.dll>]" >&2
    exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
binding="$here/../Verve"
repo="$here/../../.."
name=com.verve.agent
version=$(sed -n 's:.*<Version>\(.*\)</Version>.*:\1:p' "$binding/Verve.csproj")
mkdir -p "$1"
out=$(cd "$1" && pwd)
pkg="$out/$name"
rm -rf "$pkg" "$out/$name-$version.tgz"
mkdir -p "$pkg/Runtime" "$pkg/Plugins/Linux/x86_64"

cat >"$pkg/package.json" <<EOF
{
  "name": "$name",
  "version": "$version",
  "displayName": "Verve",
  "description": "Embeddable reinforcement-learning agents: actor-critic over a growing radial-basis-function state, with optional planning and curiosity. C# binding of the Verve C ABI with its native library.",
  "unity": "2021.2",
  "license": "MIT",
  "keywords": ["reinforcement-learning", "ai", "agent", "npc"],
  "author": { "name": "Verve contributors" }
}
EOF
cat >"$pkg/Runtime/Verve.asmdef" <<'EOF'
{
  "name": "Verve.Net",
  "rootNamespace": "Verve",
  "references": [],
  "includePlatforms": [],
  "excludePlatforms": [],
  "allowUnsafeCode": true,
  "overrideReferences": false,
  "precompiledReferences": [],
  "autoReferenced": true,
  "defineConstraints": [],
  "versionDefines": [],
  "noEngineReferences": true
}
EOF
cp "$repo/docs/csharp.md" "$pkg/README.md"
cp "$repo/LICENSE" "$pkg/LICENSE.md"
cp "$repo/THIRD_PARTY_NOTICES.md" "$pkg/THIRD_PARTY_NOTICES.md"
(cd "$binding" && find . -name '*.cs' -not -path './obj/*' -not -path './bin/*' -print0 |
    xargs -0 -I{} cp --parents {} "$pkg/Runtime/")
cp "$2/libverve.so" "$pkg/Plugins/Linux/x86_64/libverve.so"
if [[ $# -eq 3 ]]; then
    mkdir -p "$pkg/Plugins/Windows/x86_64"
    cp "$3/verve.dll" "$pkg/Plugins/Windows/x86_64/verve.dll"
fi

guid() { printf '%s' "$name/$1" | md5sum | cut -c1-32; }
meta_head() { printf 'fileFormatVersion: 2\nguid: %s\n' "$(guid "$1")"; }
asset_tail() { printf '  userData: \n  assetBundleName: \n  assetBundleVariant: \n'; }

# A native library enabled for one OS: its editor and its x86_64 standalone player, nothing else.
plugin_meta() {  # <path> <Linux|Windows>
    local linux=0 win64=0 linux_cpu=None win64_cpu=None
    if [[ $2 == Linux ]]; then linux=1 linux_cpu=x86_64; else win64=1 win64_cpu=x86_64; fi
    meta_head "$1"
    cat <<EOF
PluginImporter:
  externalObjects: {}
  serializedVersion: 2
  iconMap: {}
  executionOrder: {}
  defineConstraints: []
  isPreloaded: 0
  isOverridable: 0
  isExplicitlyReferenced: 0
  validateReferences: 1
  platformData:
  - first:
      : Any
    second:
      enabled: 0
      settings:
        Exclude Editor: 0
        Exclude Linux64: $((1 - linux))
        Exclude OSXUniversal: 1
        Exclude Win: 1
        Exclude Win64: $((1 - win64))
  - first:
      Any: 
    second:
      enabled: 0
      settings: {}
  - first:
      Editor: Editor
    second:
      enabled: 1
      settings:
        CPU: x86_64
        DefaultValueInitialized: true
        OS: $2
  - first:
      Standalone: Linux64
    second:
      enabled: $linux
      settings:
        CPU: $linux_cpu
  - first:
      Standalone: OSXUniversal
    second:
      enabled: 0
      settings:
        CPU: None
  - first:
      Standalone: Win
    second:
      enabled: 0
      settings:
        CPU: None
  - first:
      Standalone: Win64
    second:
      enabled: $win64
      settings:
        CPU: $win64_cpu
EOF
    asset_tail
}

write_meta() {  # <path relative to the package>
    local path=$1
    {
        if [[ -d $pkg/$path ]]; then
            meta_head "$path"; printf 'folderAsset: yes\nDefaultImporter:\n  externalObjects: {}\n'; asset_tail
        else
            case $path in
                *.cs) meta_head "$path"
                      printf 'MonoImporter:\n  externalObjects: {}\n  serializedVersion: 2\n  defaultReferences: []\n'
                      printf '  executionOrder: 0\n  icon: {instanceID: 0}\n'; asset_tail ;;
                *.asmdef) meta_head "$path"; printf 'AssemblyDefinitionImporter:\n  externalObjects: {}\n'; asset_tail ;;
                package.json) meta_head "$path"; printf 'PackageManifestImporter:\n  externalObjects: {}\n'; asset_tail ;;
                *.md) meta_head "$path"; printf 'TextScriptImporter:\n  externalObjects: {}\n'; asset_tail ;;
                Plugins/Linux/*) plugin_meta "$path" Linux ;;
                Plugins/Windows/*) plugin_meta "$path" Windows ;;
                *) echo "make_package: no importer for $path" >&2; exit 1 ;;
            esac
        fi
    } >"$pkg/$path.meta"
}

(cd "$pkg" && find . -mindepth 1 | sed 's:^\./::' | sort) | while read -r path; do write_meta "$path"; done

# A tarball as Unity expects it: everything under package/, reproducible.
staging=$(mktemp -d)
trap 'rm -rf "$staging"' EXIT
cp -r "$pkg" "$staging/package"
tar -C "$staging" --sort=name --mtime='UTC 2020-01-01' --owner=0 --group=0 --numeric-owner -cf - package |
    gzip -n >"$out/$name-$version.tgz"
echo "$pkg"
echo "$out/$name-$version.tgz"
