#!/usr/bin/env bash
# What accuracy costs, for your own data: renders FILE (or the embedded default, the
# tetrahedralized Wavelet of run.sh) with every integration method of 'Psi Volume' (adaptive
# sampling off and on), its interactive image (the volume level of detail), ParaView's own volume
# mappers and 'Resample To Image' at 64^3, 128^3 and 256^3 (its resampling and the level of
# detail's build timed apart from the frames), measures each image against the exact CPU
# reference at the same view, prints the table and writes DIR/report.md, DIR/accuracy.png and
# DIR/methods.png.
#   bash scripts/accuracy-report.sh [FILE|bluntfin|post|comb|spx] [--array NAME] [--out DIR]
#                                   [--size 384] [--frames 3] [--resample-dims 64 128 256]
#                                   [--no-paraview] [--back-to-front]
#
# Under an X server (scripts/lib/with-xvfb.sh: DISPLAY's, else Xvfb). The build: build/ or
# $PSI_BUILD_DIR; the NASA datasets: ../shared/data or $PSI_DATA_DIR; the report names llvmpipe's
# thread count, LP_NUM_THREADS (default: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
bash "$root/scripts/setup-deps.sh"
bash "$root/scripts/build.sh" >/dev/null
bash "$root/scripts/lib/with-xvfb.sh" pvpython --force-offscreen-rendering -m psivolume.accuracy \
  --build-dir "${PSI_BUILD_DIR:-$root/build}" ${PSI_DATA_DIR:+--data-dir "$PSI_DATA_DIR"} \
  --threads "${LP_NUM_THREADS:-all}" "$@"
