#!/usr/bin/env bash
# Added branches (Pirk 2012, 5.3.5) in one picture: the 20-year tree of type A pruned like a
# street tree (every branch off the trunk below 1 m removed), its stages at t = 0.25 and 0.5
# without and with --added, and the given tree, side by side from the front at one scale (the
# picture spans 6.2 m of height).
# Usage: scripts/stages_added_figure.sh FSPM_BINARY OUTPUT.png
set -euo pipefail
source "$(dirname "$0")/figure_common.sh"
here=$(cd "$(dirname "$0")" && pwd)

"$fspm" grow --preset A --years 20 -o "$work/a20.treeb"
"$fspm" tree convert "$work/a20.treeb" "$work/a20.tree"
python3 "$here/prune_below.py" "$work/a20.tree" 1.0 "$work/street.tree"
"$fspm" tree convert "$work/street.tree" "$work/street.treeb"
for t in 0.25 0.5; do
  "$fspm" stages "$work/street.treeb" --at "$t" -o "$work/s$t.treeb"
  "$fspm" stages "$work/street.treeb" --at "$t" --added -o "$work/s${t}_added.treeb"
done
cat >"$work/strip.json" <<JSON
{
  "fspm_scene": 2,
  "plants": [
    {"file": "s0.25.treeb", "position": [0, 0, 0]},
    {"file": "s0.25_added.treeb", "position": [2.2, 0, 0]},
    {"file": "s0.5.treeb", "position": [4.6, 0, 0]},
    {"file": "s0.5_added.treeb", "position": [7.8, 0, 0]},
    {"file": "street.treeb", "position": [11.3, 0, 0]}
  ]
}
JSON
"$fspm" render "$work/strip.json" --view front --leaves --size 1800x560 --ortho-height 6.2 -o "$out"
