#!/usr/bin/env bash
# The main job: installs what is missing, builds, and renders a dataset with 'Psi Volume' to a PNG,
# printing its frame time. With no FILE, renders the embedded default (Wavelet, tetrahedralized).
#   bash scripts/run.sh [FILE|bluntfin|post|comb] [--out image.png] [--size 512] [--method ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
bash "$root/scripts/setup-deps.sh"
bash "$root/scripts/build.sh" >/dev/null
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvpython "$root/scripts/psi_render.py" "$@"
