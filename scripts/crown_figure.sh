#!/usr/bin/env bash
# A crown from one photograph (Argudo 2014) in one picture of six panels at one scale (8 m of
# height per 256 pixels, parallel projections): the "photograph" (fspm's render of the 20-year
# tree of type A from the front), the automatic mask, the reconstructed crown from the front, from
# above and from 90 degrees, and the true tree from 90 degrees. With EXAMPLES=DIR the two renders are also
# copied to DIR (examples/crown holds them for the tests and the benchmark).
# Usage: scripts/crown_figure.sh FSPM_BINARY OUTPUT.png
set -euo pipefail
source "$(dirname "$0")/figure_common.sh"

"$fspm" grow --preset A --years 20 -o "$work/tree.treeb"
view=(--leaves --size 256x256 --ortho-height 8)
"$fspm" render "$work/tree.treeb" --view front "${view[@]}" -o "$work/tree_front.png"
"$fspm" render "$work/tree.treeb" --view side "${view[@]}" -o "$work/tree_side.png"
mkdir -p "$work/crown"
"$fspm" crown "$work/tree_front.png" --image-height-m 8 -o "$work/crown/" \
  --preview "$work/preview.png" >/dev/null
if [[ -n ${EXAMPLES:-} ]]; then
  cp "$work/tree_front.png" "$work/tree_side.png" "$EXAMPLES/"
fi

# A caption in the top left corner of a panel, dark on the renders, white on the mask.
label=(--text:x=6:y=18:size=13:font="$font")
oiiotool "$work/tree_front.png" --ch R,G,B "${label[@]}":color=0,0,0 "photograph (fspm render)" \
  -o "$work/1.png"
oiiotool "$work/crown/crown_mask.png" --ch 0,0,0 --chnames R,G,B \
  "${label[@]}":color=1,1,1 "automatic mask" -o "$work/2.png"
oiiotool "$work/preview.png" --cut 256x256+0+0 "${label[@]}":color=0,0,0 "crown, front" \
  -o "$work/3.png"
oiiotool "$work/preview.png" --cut 256x256+512+0 --origin +0+0 \
  "${label[@]}":color=0,0,0 "crown, from above" -o "$work/4.png"
oiiotool "$work/preview.png" --cut 256x256+256+0 --origin +0+0 \
  "${label[@]}":color=0,0,0 "crown, from 90 degrees" -o "$work/5.png"
oiiotool "$work/tree_side.png" --ch R,G,B "${label[@]}":color=0,0,0 "true tree, from 90 degrees" \
  -o "$work/6.png"
oiiotool "$work/1.png" "$work/2.png" "$work/3.png" "$work/4.png" "$work/5.png" "$work/6.png" \
  --mosaic:pad=4 6x1 -o "$out"
