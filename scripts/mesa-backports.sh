#!/bin/sh
# Fetches Mesa from Debian 12's bookworm-backports (25.0 at the time of writing) into DIR without
# installing it, and prints the two variables that make pvpython and pvbatch use its llvmpipe:
#   eval "$(bash scripts/mesa-backports.sh /tmp/mesa-bpo)"
#   pvpython Benchmarks/bench_scale.py ...
# The archive is the one this machine's apt uses. 'Psi Volume' gains more from the newer llvmpipe
# than 'Projected tetra' does (docs/benchmarks.md).
set -e
dir=$(mkdir -p "${1:?usage: mesa-backports.sh DIR}" && cd "$1" && pwd)
mirror=$(bash "$(dirname "$0")/lib/debian-mirror.sh")
echo "deb $mirror bookworm-backports main" > "$dir/backports.list"
mkdir -p "$dir/lists/partial" "$dir/cache/archives/partial"
opts="-o Dir::Etc::sourcelist=$dir/backports.list -o Dir::Etc::sourceparts=/dev/null
      -o Dir::State::Lists=$dir/lists -o Dir::Cache=$dir/cache"
apt-get $opts update >&2
(cd "$dir" && apt-get $opts download -t bookworm-backports libgl1-mesa-dri libglx-mesa0 \
  mesa-libgallium >&2)
for deb in "$dir"/*.deb; do dpkg-deb -x "$deb" "$dir/root"; done
lib="$dir/root/usr/lib/x86_64-linux-gnu"
echo "export LD_LIBRARY_PATH=$lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
echo "export LIBGL_DRIVERS_PATH=$lib/dri"
