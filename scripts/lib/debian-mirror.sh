#!/usr/bin/env bash
# Prints the Debian archive this machine's apt is configured with (the first non-security
# "debian" URI of its sources), so that the scripts never name a mirror host themselves.
#   mirror=$(bash scripts/lib/debian-mirror.sh)
set -eu
uris=$(
  {
    # deb822 sources: "URIs: http://host/debian"
    cat /etc/apt/sources.list.d/*.sources 2>/dev/null | sed -n 's/^URIs:[[:space:]]*//p' | tr ' ' '\n'
    # one-line sources: "deb [options] http://host/debian suite components"
    cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
      sed -n 's/^deb[[:space:]]\{1,\}\(\[[^]]*\][[:space:]]\{1,\}\)\{0,1\}\([^[:space:]]\{1,\}\).*/\2/p'
  } | grep -E '^(https?|file)://[^ ]*/debian/?$' || true)
if [ -z "$uris" ]; then
  echo "debian-mirror: no Debian archive (a URI ending in /debian) in /etc/apt/sources.list{,.d}" >&2
  exit 1
fi
printf '%s\n' "$uris" | sed -n '1{s:/$::;p;}'
