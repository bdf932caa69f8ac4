#!/usr/bin/env bash
# Fails if any tracked file names a package host: a Debian or Ubuntu mirror, NuGet, npm, PyPI, Rust's
# crates registry, RubyGems, Maven Central, the Go module proxy, Packagist, LuaRocks, Docker Hub, Microsoft's or Mono's
# package feeds. Where packages come from is the machine's business (its apt sources, the .NET SDK's
# configured NuGet sources), never the repository's: scripts/fetch_source.sh reads the mirror from the
# machine's apt sources. Nothing is allowed, docs included; a link to documentation (learn.microsoft.com,
# docs.godotengine.org) is not a package host and passes. Run by scripts/test.sh before anything else.
#   ./scripts/check_no_hosts.sh        -> lists each offending line, exit 1 if there is one
# The patterns write each dot as [.] so that this file does not match itself.
set -euo pipefail
cd "$(dirname "$0")/.."

hosts=(
  '([a-z0-9-]+[.])*debian[.](org|net)'        # deb., security., ftp.<cc>., snapshot., cdn-aws. ...
  '([a-z0-9-]+[.])*ubuntu[.]com'              # archive., security., ports., <cc>.archive.
  'ppa[.]launchpad(content)?[.]net'
  '([a-z0-9-]+[.])*nuget[.](org|pkg[.]github[.]com)'
  'nugetgallery[.]blob[.]core[.]windows[.]net'
  '([a-z0-9-]+[.])*npmjs[.](org|com)'
  'registry[.]yarnpkg[.]com'
  '([a-z0-9-]+[.])*pypi[.](org|python[.]org)'
  'files[.]pythonhosted[.]org'
  '([a-z0-9-]+[.])*crates[.]io'
  '([a-z0-9-]+[.])*rubygems[.]org'
  'repo1?[.]maven[.](org|apache[.]org)'
  '(proxy|sum)[.]golang[.]org'
  '([a-z0-9-]+[.])*packagist[.]org'
  '([a-z0-9-]+[.])*luarocks[.]org'
  '(registry-1|hub|index)[.]docker[.]io'
  'packages[.]microsoft[.]com'
  'download[.]mono-project[.]com'
  'dotnetcli[.]azureedge[.]net'
  'builds[.]dotnet[.]microsoft[.]com'
  'dl-cdn[.]alpinelinux[.]org'
)
pattern="(^|[^a-z0-9.-])($(IFS='|'; echo "${hosts[*]}"))([^a-z0-9-]|$)"

# The check must catch what it is for: each host pattern, written out as a plain name (its first
# alternative, optional parts kept), is caught in a URL, an apt source line and a NuGet source, so
# that this file names no host itself.
scheme=https
for h in "${hosts[@]}"; do
  sample=$(sed -E 's/\(\[a-z0-9-\]\+\[\.\]\)\*//g; s/\[\.\]/./g; s/\(([^|)]*)(\|[^)]*)?\)\??/\1/g; s/\?//g' <<<"$h")
  url="${scheme}://$sample/x"
  for planted in "$url" "URIs: $url" "deb $url suite main" "<add key=\"x\" value=\"$url\" />"; do
    grep -q -i -E "$pattern" <<<"$planted" || { echo "check_no_hosts.sh: the pattern misses: $planted" >&2; exit 2; }
  done
done
for fine in "https://learn.microsoft.com/dotnet/core/install/linux-debian" "apt-get install godot3-server" \
    "Debian 12 (bookworm)" "the NuGet package" "PyPI"; do
  if grep -q -i -E "$pattern" <<<"$fine"; then echo "check_no_hosts.sh: the pattern wrongly matches: $fine" >&2; exit 2; fi
done

if found=$(git ls-files -z | xargs -0 grep -I -n -i -E "$pattern" --); then
  echo "$found" >&2
  echo "check_no_hosts.sh: the lines above name a package host; take it from the machine's configuration instead" >&2
  exit 1
fi
echo "check_no_hosts.sh: no package host named in $(git ls-files | wc -l) tracked files"
