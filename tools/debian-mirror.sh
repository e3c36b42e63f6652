#!/usr/bin/env bash
# The Debian mirror this machine's apt takes bookworm from, for debootstrap: no script of the
# project names a mirror's host.
#   tools/debian-mirror.sh                   prints the mirror's URI
#   tools/debian-mirror.sh --copy-sources D  copies this machine's bookworm source files into
#                                            the system at D (other vendors' need keys it lacks)
set -euo pipefail
if [ "${1:-}" = "--copy-sources" ]; then
  dest=$2
  rm -f "$dest/etc/apt/sources.list"
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
    if [ -f "$f" ] && grep -Eq '(^|[[:space:]])bookworm(-updates|-security)?([[:space:]]|$)' "$f"; then
      cp "$f" "$dest/etc/apt/${f#/etc/apt/}"
    fi
  done
  exit 0
fi
# A one-line "deb [options] URI bookworm ...", else a deb822 stanza whose Suites hold bookworm.
mirror=$(
  { cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null || true; } |
    awk '$1 == "deb" { i = 2; if ($i ~ /^\[/) { while (i <= NF && $i !~ /\]$/) i++; i++ }
                       if ($(i + 1) == "bookworm") { print $i; exit } }'
)
if [ -z "$mirror" ]; then
  mirror=$(
    { cat /etc/apt/sources.list.d/*.sources 2>/dev/null || true; echo; } |
      awk '/^[ \t]*$/ { if (uris != "" && suites ~ / bookworm( |$)/) { print uris; exit }
                        uris = ""; suites = "" }
           /^URIs:/ { uris = $2 }
           /^Suites:/ { $1 = ""; suites = $0 " " }'
  )
fi
[ -n "$mirror" ] || { echo "debian-mirror: error: no bookworm source in /etc/apt" >&2; exit 2; }
echo "$mirror"
