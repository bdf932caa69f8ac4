# Sourced by scripts that fetch from Debian (fetch_source.sh, build_old_glibc.sh): the machine's own
# mirror, so the repository names no package host.
#   debian_mirror [ETC]  -> prints "URI|SUITE|COMPONENTS|SIGNED-BY" (empty fields allowed), or nothing
# The mirror is the first release suite (no "-updates"/"-security") of a "deb" entry in
# ETC/sources.list.d/*.sources (deb822) or ETC/sources.list{,.d/*.list} (one-line form); ETC is
# /etc/apt unless given (scripts/check_fetch_source_mirror.sh points it at fake folders).
debian_mirror() {
  local etc=${1:-/etc/apt} found
  found=$(
    { cat "$etc"/sources.list.d/*.sources 2>/dev/null; echo; } | awk '
      function flush() {
        if (types ~ /(^| )deb( |$)/ && uri != "" && suite != "")
          { print uri "|" suite "|" comps "|" signed; found = 1; exit }
        types = uri = suite = comps = signed = ""
      }
      /^[ \t]*$/ { flush(); next }
      /^#/ { next }
      /^Types:/ { sub(/^Types:[ \t]*/, ""); types = $0 }
      /^URIs:/ { uri = $2 }
      /^Suites:/ { for (i = 2; i <= NF; i++) if ($i !~ /-/) { suite = $i; break } }
      /^Components:/ { sub(/^Components:[ \t]*/, ""); comps = $0 }
      /^Signed-By:/ { signed = $2 }
      END { if (!found) flush() }' || true
  )
  if [ -z "$found" ]; then
    found=$(cat "$etc/sources.list" "$etc"/sources.list.d/*.list 2>/dev/null | awk '
      $1 == "deb" {
        i = 2; opts = ""
        if ($i ~ /^\[/) { while ($i !~ /\]$/) opts = opts " " $(i++); opts = opts " " $(i++) }
        if ($(i + 1) ~ /-/) next
        signed = ""; if (match(opts, /signed-by=[^] ]+/)) signed = substr(opts, RSTART + 10, RLENGTH - 10)
        comps = ""; for (j = i + 2; j <= NF; j++) comps = comps (comps ? " " : "") $j
        print $i "|" $(i + 1) "|" comps "|" signed; exit
      }' || true)
  fi
  if [ -n "$found" ]; then echo "$found"; fi
}
