#!/usr/bin/env bash
# The main job: installs what is missing, builds Release, and runs a small end-to-end study:
# a parameter sweep of an L-system tree through the experiment runner (results in SQLite and
# CSV), a GreenLab plant simulated and reconstructed at three ages, and a mesh of one tree.
# It ends by saying where its output is.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)"
out=demo-output
rm -rf "$out"
mkdir -p "$out"
fspm=build/bin/fspm

echo "== parameter sweep: Honda's monopodial tree (ABOP fig. 2.6), 36 runs"
$fspm run examples/experiments/branching.toml --out "$out/branching" --jobs "$(nproc)"
$fspm results show "$out/branching"
$fspm results export "$out/branching" --csv -o "$out/branching/results.csv"
$fspm report "$out/branching"

echo "== an L-system tree"
$fspm lsystem interpret examples/lsystems/monopodial_tree.l -o "$out/monopodial.tree"
$fspm tree info "$out/monopodial.tree"
$fspm tree convert "$out/monopodial.tree" "$out/monopodial.mtg"

echo "== a GreenLab plant (Jaeger's Leeuwenberg example) reconstructed at ages 2, 4 and 6"
$fspm greenlab simulate examples/greenlab/leeuwenberg.toml -o "$out/leeuwenberg.ctree" --json
for age in 2 4 6; do
  $fspm greenlab reconstruct "$out/leeuwenberg.ctree" --age "$age" -o "$out/leeuwenberg-$age.tree" --json
done

echo "== a mesh for ParaView or Blender"
$fspm mesh "$out/monopodial.tree" -o "$out/monopodial.glb" --json

echo
echo "demo output is in $(pwd)/$out (sweep: $out/branching/results.csv and $out/branching/report.md)"
