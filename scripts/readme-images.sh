#!/usr/bin/env bash
# Makes the README's pictures in docs/:
#   psi_volume.png  the Blunt Fin (or, without ../shared/data, the embedded default) rendered by
#                   scripts/run.sh;
#   panel.png       the real paraview client with 'Psi Volume' shown and its Properties panel, as
#                   scripts/panel_screenshot.py sets it up (the screen of an Xvfb server, kept in a
#                   file by -fbdir, converted by scripts/xwd_to_png.py); the window is tall
#                   (Qt's -geometry) so that the panel shows every 'Psi Volume' group.
# The speed plot (docs/speed_scale.png) is drawn by the benchmark itself (bench_scale.py --plot).
#   bash scripts/readme-images.sh [--panel-only]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/scripts/lib/python-path.sh"
. "$root/scripts/lib/paraview-versions.sh"
bash "$root/scripts/build.sh" >/dev/null
if [ "${1:-}" != "--panel-only" ]; then
  scene=bluntfin
  [ -e "$root/../shared/data/MANIFEST.md" ] || scene=""
  bash "$root/scripts/run.sh" $scene --out "$root/docs/psi_volume.png"
fi

work=$(mktemp -d)
trap 'kill "${client:-}" "${xvfb:-}" 2>/dev/null || true; rm -rf "$work"' EXIT
display=:$((200 + RANDOM % 100))
Xvfb "$display" -noreset -screen 0 1400x1900x24 -fbdir "$work" >/dev/null 2>&1 &
xvfb=$!
sleep 2
series=$(installed_paraview_series)
plugin_dir="$root/build/lib/paraview-$series/plugins/PsiVolume"
DISPLAY=$display PSI_SCREENSHOT_READY="$work/ready" paraview -geometry 1400x1900+0+0 --dr \
  --plugin-search-paths="$plugin_dir" --script="$root/scripts/panel_screenshot.py" \
  >"$work/client.log" 2>&1 &
client=$!
for _ in $(seq 120); do
  [ -e "$work/ready" ] && break
  kill -0 "$client" 2>/dev/null || { cat "$work/client.log" >&2; exit 1; }
  sleep 1
done
[ -e "$work/ready" ] || { echo "readme-images: the client did not get ready" >&2; exit 1; }
sleep 10 # the client shows the source, frames the view and fills the panel after the script
pvpython "$root/scripts/xwd_to_png.py" "$work/Xvfb_screen0" "$root/docs/panel.png"
echo "wrote docs/panel.png"
