#!/usr/bin/env bash
# Developmental stages against known history: trees of types A, B and C grown 30 years (seed 1)
# are turned into developmental models (which read only their geometry: no ages, birth times or
# shedding history), and the stages at t = 10/30 and 20/30 are compared with the same trees as
# they were at 10 and 20 years (grown again to that age with the same seed), and with an
# independently grown tree of that age (seed 2). One Markdown table row per type and age
# (docs/stages.md). FSPM=path/to/fspm to use a build.
set -euo pipefail
fspm=${FSPM:-fspm}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
info() { $fspm -q tree info "$1" --json; }
distance() {
  $fspm -q distance "$1" "$2" --cost standardized --main-skeleton 0.01 --json |
    /usr/bin/python3 -c "import json, sys; print(json.load(sys.stdin)['distance'])"
}
echo "| type, age | internodes: stage / recorded / other | height m | crown width m | distance stage-recorded | distance other-recorded |"
echo "|---|---|---|---|---|---|"
for type in A B C; do
  $fspm -q grow --preset $type --years 30 --seed 1 -o $work/final.treeb
  for years in 10 20; do
    $fspm -q grow --preset $type --years $years --seed 1 -o $work/recorded.treeb
    $fspm -q grow --preset $type --years $years --seed 2 -o $work/other.treeb
    $fspm -q stages $work/final.treeb --at $(/usr/bin/python3 -c "print($years / 30)") \
      -o $work/stage.treeb
    s=$(info $work/stage.treeb); r=$(info $work/recorded.treeb); o=$(info $work/other.treeb)
    d_stage=$(distance $work/stage.treeb $work/recorded.treeb)
    d_other=$(distance $work/other.treeb $work/recorded.treeb)
    /usr/bin/python3 - "$s" "$r" "$o" "$d_stage" "$d_other" "$type" "$years" <<'PY'
import json, sys
s, r, o = (json.loads(x) for x in sys.argv[1:4])
d_stage, d_other, t, y = float(sys.argv[4]), float(sys.argv[5]), sys.argv[6], sys.argv[7]
print(f"| {t}, {y} y | {s['internodes']} / {r['internodes']} / {o['internodes']} "
      f"| {s['height']:.2f} / {r['height']:.2f} / {o['height']:.2f} "
      f"| {s['crown_width']:.2f} / {r['crown_width']:.2f} / {o['crown_width']:.2f} "
      f"| {d_stage:.0f} | {d_other:.0f} |")
PY
  done
done
