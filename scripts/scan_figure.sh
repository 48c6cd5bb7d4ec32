#!/usr/bin/env bash
# Encoding and decoding a simulated scan (Pirk 2013, ch. 3) in one picture of four panels, all
# drawn from the front at one scale and framed on the scan's points so that they line up:
# the scanned points, the main skeleton, the skeleton with the cluster hulls, and the decoded tree.
# Usage: scripts/scan_figure.sh FSPM_BINARY OUTPUT.png [TREE]
set -euo pipefail
figure_usage_tail=" [TREE]"
source "$(dirname "$0")/figure_common.sh"
tree=${3:-$(dirname "$0")/../examples/trees/open_a12.treeb}

"$fspm" scan "$tree" -o "$work/scan.ply" --seed 1
# The trunk-circle fit overestimates d_root on a tree branching near the ground (docs/scans.md),
# so the true base diameter is given. The main skeleton follows the trunk and the main limbs (the
# default); eq. 3.2 with Table 3.1's f_s sends the thinner branches to the clusters. The radii of
# eq. 3.1 are drawn with the pipe model's gamma 0.5 (GAMMA overrides it): at Table 3.1's 1.2-1.9
# the limbs of this young tree are a few millimetres thick and vanish at this scale. FS=F sets
# f_s, PIRK=1 draws Pirk's split (eq. 3.2 alone).
"$fspm" encode "$work/scan.ply" -o "$work/tree.clusters" --root-diameter 0.075 \
  --gamma "${GAMMA:-0.5}" ${FS:+--fs "$FS"} ${PIRK:+--pirk-split} --skeleton "$work/skeleton.tree"
"$fspm" decode "$work/tree.clusters" -o "$work/decoded.tree" --seed 1

view=(--view front --size 400x450 --ortho-height "${ORTHO_HEIGHT_M:-5.6}" --frame "$work/scan.ply")
"$fspm" render "$work/scan.ply" -o "$work/1_points.png" "${view[@]}"
"$fspm" render "$work/skeleton.tree" -o "$work/2_skeleton.png" "${view[@]}"
"$fspm" render "$work/tree.clusters" -o "$work/3_clusters.png" "${view[@]}"
"$fspm" render "$work/decoded.tree" -o "$work/4_decoded.png" --leaves "${view[@]}"
oiiotool "$work/1_points.png" "$work/2_skeleton.png" "$work/3_clusters.png" \
  "$work/4_decoded.png" --mosaic 4x1 --ch R,G,B -o "$out"
