#!/usr/bin/env bash
# The main job: installs what is missing, builds, and renders a dataset with 'Psi Volume' to a PNG,
# printing its frame time. With no FILE, renders the embedded default (Wavelet, tetrahedralized).
#   bash scripts/run.sh [FILE|bluntfin|post|comb] [--out image.png] [--size 512] [--method ...]
# Under an X server (scripts/lib/with-xvfb.sh: DISPLAY's, else Xvfb). The build: build/ or
# $PSI_BUILD_DIR; the NASA datasets: ../shared/data or $PSI_DATA_DIR.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
bash "$root/scripts/setup-deps.sh"
bash "$root/scripts/build.sh" >/dev/null
bash "$root/scripts/lib/with-xvfb.sh" pvpython "$root/scripts/psi_render.py" \
  --build-dir "${PSI_BUILD_DIR:-$root/build}" ${PSI_DATA_DIR:+--data-dir "$PSI_DATA_DIR"} "$@"
