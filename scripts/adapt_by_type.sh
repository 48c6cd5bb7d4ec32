#!/usr/bin/env bash
# The open-grown tree of every type, age and tropism pairing adapted to the wall of the
# adapted-versus-grown experiment (4 m high, 2 m east of the trunk): one Markdown table row each
# (docs/environment.md, "Answering the wall, type by type"). FSPM=path/to/fspm to use a build.
set -euo pipefail
fspm=${FSPM:-fspm}
wall=${WALL:-examples/experiments/adapted_vs_grown_wall.json}
work=$(mktemp -d)
declare -A photo=([A-text]=0.25 [A-appendix]=0.25 [B-text]=0.45 [B-appendix]=0.45 [C-text]=0.03 [C-appendix]=0.44)
declare -A gravi=([A-text]=0.12 [A-appendix]=0.12 [B-text]=0.44 [B-appendix]=0.03 [C-text]=0.23 [C-appendix]=0.23)
for pairing in text appendix; do
  for type in A B C; do
    for years in 10 20 30; do
      $fspm grow --preset $type --tropisms $pairing --years $years -o $work/open.treeb > /dev/null
      $fspm adapt $work/open.treeb --scene "$wall" -o $work/adapted.treeb --json \
        --phototropism ${photo[$type-$pairing]} --gravitropism ${gravi[$type-$pairing]} \
        | /usr/bin/python3 -c "
import json, sys
r = json.load(sys.stdin)
p, c, s = r['pruned_centroid'], r['internode_centroid'], r['mean_tip_shift']
side = 'wall' if r['pruned_nodes'] and p[0] > c[0] else ('far' if r['pruned_nodes'] else '-')
print(f\"| $pairing | $type, $years y | {r['nodes']} | {s[0]:+.2f} | {r['pruned_nodes']} | {p[0]:+.2f} / {c[0]:+.2f} ({side}) |\")"
    done
  done
done
rm -rf "$work"
