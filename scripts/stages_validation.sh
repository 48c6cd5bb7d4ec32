#!/usr/bin/env bash
# Developmental stages against known history: trees of types A, B and C grown 30 years (seed 1)
# are turned into developmental models (which read only their geometry: no ages, birth times or
# shedding history), and the stages at t = 10/30 and 20/30 are compared with the same trees as
# they were at 10 and 20 years (grown again to that age with the same seed), and with an
# independently grown tree of that age (seed 2). One Markdown table row per type and age
# (docs/stages.md), with two models side by side:
#   - eq. 5.3: the tree grown as by default (radii from its living branches), constant rates;
#   - shed: the same tree with the pipes of its shed branches kept in its radii
#     (keep_shed_pipes, as in real wood), its shed branches reconstructed from them
#     (--shed-branches), with constant rates and with rates by chain (--growth-profiles by_chain).
# Columns "new" are the last of these. Its distances are to the recorded and other trees grown
# with keep_shed_pipes too (the same internodes, radii of the same kind of wood).
# A second table gives, per type and growth profile choice, how far the time each surviving
# internode starts growing in the model (t * 30 years) is from the year it grew in (its birth
# time in the grown tree): mean error and mean absolute error in years, and the share of the
# 20-year tree's internodes still in the 30-year tree (born by year 20), the most any model of
# the 30-year tree's own branches can hold at t = 2/3.
# FSPM=path/to/fspm to use a build.
set -euo pipefail
fspm=${FSPM:-fspm}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
info() { $fspm -q tree info "$1" --json; }
distance() {
  $fspm -q distance "$1" "$2" --cost standardized --main-skeleton 0.01 --json |
    /usr/bin/python3 -c "import json, sys; print(json.load(sys.stdin)['distance'])"
}
echo "| type, age | internodes: eq. 5.3 / shed / shed + by_chain / recorded / other | new / recorded (old) | height m: old / new / recorded / other | crown width m: old / new / recorded / other | distance to recorded, old: stage / other | new: stage / other |"
echo "|---|---|---|---|---|---|---|"
for type in A B C; do
  $fspm -q grow --preset $type --years 30 --seed 1 -o "$work"/final.treeb
  $fspm -q grow --preset $type --years 30 --seed 1 --set keep_shed_pipes=true \
    -o "$work"/final_pipes.treeb
  for years in 10 20; do
    $fspm -q grow --preset $type --years $years --seed 1 -o "$work"/recorded.treeb
    $fspm -q grow --preset $type --years $years --seed 2 -o "$work"/other.treeb
    for seed in 1 2; do
      $fspm -q grow --preset $type --years $years --seed $seed --set keep_shed_pipes=true \
        -o "$work"/pipes_$seed.treeb
    done
    t=$(/usr/bin/python3 -c "print($years / 30)")
    $fspm -q stages "$work"/final.treeb --at "$t" -o "$work"/old.treeb
    $fspm -q stages "$work"/final_pipes.treeb --at "$t" --shed-branches -o "$work"/shed.treeb
    $fspm -q stages "$work"/final_pipes.treeb --at "$t" --shed-branches \
      --growth-profiles by_chain -o "$work"/new.treeb
    old=$(info "$work"/old.treeb); shed=$(info "$work"/shed.treeb); new=$(info "$work"/new.treeb)
    r=$(info "$work"/recorded.treeb); o=$(info "$work"/other.treeb)
    d_old=$(distance "$work"/old.treeb "$work"/recorded.treeb)
    d_other=$(distance "$work"/other.treeb "$work"/recorded.treeb)
    d_new=$(distance "$work"/new.treeb "$work"/pipes_1.treeb)
    d_new_other=$(distance "$work"/pipes_2.treeb "$work"/pipes_1.treeb)
    /usr/bin/python3 - "$old" "$shed" "$new" "$r" "$o" "$d_old" "$d_other" "$d_new" \
      "$d_new_other" "$type" "$years" <<'PY'
import json, sys
old, shed, new, r, o = (json.loads(x) for x in sys.argv[1:6])
d_old, d_other, d_new, d_new_other = (float(x) for x in sys.argv[6:10])
t, y = sys.argv[10], sys.argv[11]
n = lambda d: d['internodes']
print(f"| {t}, {y} y | {n(old)} / {n(shed)} / {n(new)} / {n(r)} / {n(o)} "
      f"| {n(new) / n(r):.2f} ({n(old) / n(r):.2f}) "
      f"| {old['height']:.2f} / {new['height']:.2f} / {r['height']:.2f} / {o['height']:.2f} "
      f"| {old['crown_width']:.2f} / {new['crown_width']:.2f} / {r['crown_width']:.2f} / "
      f"{o['crown_width']:.2f} | {d_old:.0f} / {d_other:.0f} | {d_new:.0f} / {d_new_other:.0f} |")
PY
  done
done
echo
echo "| type | 20-year internodes still there at 30 years | birth year, model minus grown, mean / mean absolute: constant (eq. 5.3) | by_chain | logistic | accelerating |"
echo "|---|---|---|---|---|---|"
for type in A B C; do
  $fspm -q grow --preset $type --years 30 --seed 1 -o "$work"/final.tree
  $fspm -q grow --preset $type --years 20 --seed 1 -o "$work"/recorded.treeb
  recorded=$($fspm -q tree info "$work"/recorded.treeb --json |
    /usr/bin/python3 -c "import json, sys; print(json.load(sys.stdin)['internodes'])")
  kept=$(/usr/bin/python3 - "$work"/final.tree <<'PY'
import sys
print(sum(1 for line in open(sys.argv[1]) if len(line.split()) > 16 and line.split()[0].isdigit()
          and line.split()[2] == "internode" and float(line.split()[16]) <= 20))
PY
)
  row="| $type | $kept of $recorded ($(/usr/bin/python3 -c "print(f'{$kept / $recorded:.2f}')")) |"
  for profiles in constant by_chain logistic accelerating; do
    $fspm -q stages "$work"/final.tree --at 1 --growth-profiles $profiles -o "$work"/start.tree
    row+=$(/usr/bin/python3 - "$work"/final.tree "$work"/start.tree <<'PY'
import sys
def births(path):
    out = []
    for line in open(path):
        f = line.split()
        if len(f) > 16 and f[0].isdigit() and f[2] == "internode":
            out.append(float(f[16]))
    return out
grown, model = births(sys.argv[1]), births(sys.argv[2])
assert len(grown) == len(model)
e = [30 * m - g for g, m in zip(grown, model)]
print(f" {sum(e) / len(e):.2f} / {sum(abs(x) for x in e) / len(e):.2f} |", end="")
PY
)
  done
  echo "$row"
done
