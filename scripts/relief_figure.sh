#!/usr/bin/env bash
# A crown from one photograph in the viewer, drawn as its mesh and by relief-mapped ray casting
# of its cubemaps (Argudo 2014, 5.1), side by side, both with the viewer's shadows.
# Usage: scripts/relief_figure.sh FSPM_BINARY OUTPUT.png   (needs an X display or xvfb-run)
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 FSPM_BINARY OUTPUT.png" >&2
  exit 2
fi
fspm=$1
out=$2
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
font=${FONT:-/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf}

"$fspm" crown "$here/examples/crown/tree_front.png" --image-height-m 8 --trunk-m 1.5 \
  -o "$work/crown/" >/dev/null
view=(--no-panel --size 480x360 --pitch-deg 12)
"$fspm" view "$work/crown/crown.glb" "${view[@]}" --screenshot "$work/mesh.png"
"$fspm" view "$work/crown/crown.glb" --ray-cast "${view[@]}" --screenshot "$work/relief.png"

label=(--text:x=8:y=20:size=14:font="$font":color=0,0,0)
oiiotool "$work/mesh.png" --ch R,G,B "${label[@]}" "the crown's mesh" -o "$work/1.png"
oiiotool "$work/relief.png" --ch R,G,B "${label[@]}" "ray cast from its cubemaps (--ray-cast)" \
  -o "$work/2.png"
oiiotool "$work/1.png" "$work/2.png" --mosaic:pad=4 2x1 -o "$out"
