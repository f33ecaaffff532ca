#!/usr/bin/env bash
# Makes the README's pictures in docs/:
#   psi_volume.png  the Blunt Fin (or, without the shared data, ../shared/data or
#                   $PSI_DATA_DIR, the embedded default) rendered by scripts/run.sh;
#   intermixed.png  two volumes in one view, 'Psi Volume' against 'Volume' in both show orders
#                   (scripts/intermixed_picture.py);
#   panel.png       the real paraview client with 'Psi Volume' shown and its Properties panel, as
#                   scripts/panel_screenshot.py sets it up (the screen of an Xvfb server of
#                   scripts/lib/with-xvfb.sh, kept in a file by its --fbdir, converted by
#                   scripts/xwd_to_png.py); the window is tall (Qt's -geometry) so that the
#                   panel shows every 'Psi Volume' group.
# The speed plot (docs/speed_scale.png) is drawn by the benchmark itself (bench_scale.py --plot).
#   bash scripts/readme-images.sh [--panel-only]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
. "$root/scripts/lib/paraview-versions.sh"
bash "$root/scripts/build.sh" >/dev/null
if [ "${1:-}" != "--panel-only" ]; then
  scene=bluntfin
  [ -e "${PSI_DATA_DIR:-$root/../shared/data}/MANIFEST.md" ] || scene=""
  bash "$root/scripts/run.sh" $scene --out "$root/docs/psi_volume.png"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build=${PSI_BUILD_DIR:-$root/build}
plugin_dir="$build/lib/paraview-$(installed_paraview_series)/plugins/PsiVolume"
if [ "${1:-}" != "--panel-only" ]; then
  bash "$root/scripts/lib/with-xvfb.sh" pvpython --force-offscreen-rendering \
    "$root/scripts/intermixed_picture.py" "$plugin_dir/PsiVolume.so" "$root/docs/intermixed.png"
fi
# paraview passes its --script no arguments: a script of two lines gives panel_screenshot.py its own.
printf 'import sys\nsys.argv = [%s, %s, %s]\nexec(open(sys.argv[0]).read())\n' \
  "'$root/scripts/panel_screenshot.py'" "'$work/ready'" "'$build'" > "$work/panel.py"
# The client in an X server of its own whose screen is kept in a file (-fbdir), converted once
# the client is ready; the client ends with the server.
bash "$root/scripts/lib/with-xvfb.sh" --screen 1400x1900x24 --fbdir "$work" bash -c '
  work=$1 plugin_dir=$2 root=$3
  paraview -geometry 1400x1900+0+0 --dr --plugin-search-paths="$plugin_dir" \
    --script="$work/panel.py" >"$work/client.log" 2>&1 &
  client=$!
  trap "kill $client 2>/dev/null || true" EXIT
  for _ in $(seq 120); do
    [ -e "$work/ready" ] && break
    kill -0 "$client" 2>/dev/null || { cat "$work/client.log" >&2; exit 1; }
    sleep 1
  done
  [ -e "$work/ready" ] || { echo "readme-images: the client did not get ready" >&2; exit 1; }
  sleep 10 # the client shows the source, frames the view and fills the panel after the script
  pvpython "$root/scripts/xwd_to_png.py" "$work/Xvfb_screen0" "$root/docs/panel.png"
' panel "$work" "$plugin_dir" "$root"
echo "wrote docs/panel.png"
