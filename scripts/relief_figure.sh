#!/usr/bin/env bash
# A crown from one photograph in the viewer, drawn as its mesh, by relief-mapped ray casting of
# its cubemaps (Argudo 2014, 5.1), and close up as the detailed crown of leaf billboards (5.2),
# side by side, all with the viewer's shadows. The close view is the middle of a 1440 x 1080
# screenshot, where the crown is large enough on the screen for billboards.
# Usage: scripts/relief_figure.sh FSPM_BINARY OUTPUT.png   (needs an X display or xvfb-run)
set -euo pipefail
source "$(dirname "$0")/figure_common.sh"
here=$(cd "$(dirname "$0")/.." && pwd)

"$fspm" crown "$here/examples/crown/tree_front.png" --image-height-m 8 --trunk-m 1.5 \
  -o "$work/crown/" >/dev/null
view=(--no-panel --size 480x360 --pitch-deg 12)
"$fspm" view "$work/crown/crown.glb" "${view[@]}" --screenshot "$work/mesh.png"
"$fspm" view "$work/crown/crown.glb" --ray-cast "${view[@]}" --screenshot "$work/relief.png"
"$fspm" view "$work/crown/crown.glb" --ray-cast --no-panel --size 1440x1080 --pitch-deg 12 \
  --screenshot "$work/near_full.png"
oiiotool "$work/near_full.png" --cut 960x720+250+140 --resize 480x360 -o "$work/near.png"

label=(--text:x=8:y=20:size=14:font="$font":color=0,0,0)
oiiotool "$work/mesh.png" --ch R,G,B "${label[@]}" "the crown's mesh" -o "$work/1.png"
oiiotool "$work/relief.png" --ch R,G,B "${label[@]}" "ray cast from its cubemaps (--ray-cast)" \
  -o "$work/2.png"
oiiotool "$work/near.png" --ch R,G,B "${label[@]}" "close up: leaf billboards" -o "$work/3.png"
oiiotool "$work/1.png" "$work/2.png" "$work/3.png" --mosaic:pad=4 3x1 -o "$out"
