#!/usr/bin/env bash
# Shadow cascades in the viewer: the 11 000-tree landscape of examples/landscape seen from 30 m,
# with the one shadow map of the whole scene (each texel about 2.4 m of ground) and with three
# cascades over the view (fspm view --shadow-cascades 3), side by side.
# Usage: scripts/cascades_figure.sh FSPM_BINARY OUTPUT.png   (needs an X display or xvfb-run)
set -euo pipefail
source "$(dirname "$0")/figure_common.sh"
here=$(cd "$(dirname "$0")/.." && pwd)

view=(view "$here/examples/landscape/landscape.json" --leaves --lod --no-panel --size 640x400
  --frames 2 --distance 30 --pitch-deg 30 --yaw-deg 51)
"$fspm" "${view[@]}" --screenshot "$work/one.png"
"$fspm" "${view[@]}" --shadow-cascades 3 --screenshot "$work/cascades.png"
# Each caption on a white strip above its image.
captioned() {
  oiiotool "$1" --ch R,G,B --pattern constant:color=1,1,1 640x426 3 --paste +0+26 \
    --text:x=8:y=19:size=14:font="$font":color=0,0,0 "$2" -o "$3"
}
captioned "$work/one.png" "one shadow map of the whole scene (2.4 m texels)" "$work/1.png"
captioned "$work/cascades.png" "three cascades (fspm view --shadow-cascades 3)" "$work/2.png"
oiiotool "$work/1.png" "$work/2.png" --mosaic:pad=4 2x1 -o "$out"
