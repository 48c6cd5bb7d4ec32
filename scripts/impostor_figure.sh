#!/usr/bin/env bash
# Impostors in the viewer: 36 GreenLab plants (Massart's and Leeuwenberg's models, each turned
# differently) drawn at full detail and, with --lod --lod-distance 1, every one as an impostor,
# one quad showing the plant from the nearest of 24 directions, side by side with the triangles
# and the frame time each took.
# Usage: scripts/impostor_figure.sh FSPM_BINARY OUTPUT.png   (needs an X display or xvfb-run)
set -euo pipefail
source "$(dirname "$0")/figure_common.sh"
here=$(cd "$(dirname "$0")/.." && pwd)

{
  echo '{"fspm_scene": 2, "plants": ['
  for i in 0 1 2 3 4 5; do
    for j in 0 1 2 3 4 5; do
      k=$((i * 6 + j))
      model=massart
      [[ $((k % 3)) -eq 0 ]] && model=leeuwenberg
      [[ $k -gt 0 ]] && echo ','
      echo "{\"file\": \"$here/examples/greenlab/$model.toml\", \"position\": [$((12 * i)), $((12 * j)), 0], \"rotation_deg\": $((37 * k % 360))}"
    done
  done
  echo ']}'
} > "$work/grid.json"
view=(--leaves --no-panel --size 640x400 --frames 3 --json)
full=$("$fspm" view "$work/grid.json" --full-detail "${view[@]}" --screenshot "$work/full.png")
impostors=$("$fspm" view "$work/grid.json" --lod --lod-distance 1 "${view[@]}" \
  --screenshot "$work/impostors.png")
caption() {  # "N triangles, M ms a frame" from the view's --json, the first frame left out
  /usr/bin/python3 - "$1" <<'PY'
import json, sys
j = json.loads(sys.argv[1])
n = j["frames"]
ms = (j["mean_frame_ms"] * n - j["first_frame_ms"]) / (n - 1)
print(f"{j['triangles']:,} triangles, {ms:.0f} ms a frame")
PY
}
label=(--text:x=8:y=20:size=14:font="$font":color=0,0,0)
oiiotool "$work/full.png" --ch R,G,B "${label[@]}" "full detail: $(caption "$full")" \
  -o "$work/1.png"
oiiotool "$work/impostors.png" --ch R,G,B "${label[@]}" "impostors: $(caption "$impostors")" \
  -o "$work/2.png"
oiiotool "$work/1.png" "$work/2.png" --mosaic:pad=4 2x1 -o "$out"
