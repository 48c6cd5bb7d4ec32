#!/usr/bin/env bash
# The main job: installs what is missing, builds Release, and runs a small end-to-end study:
# a small version of Pirk's adapted-versus-grown experiment through the experiment runner (grow,
# adapt, compare, t-test, report), a parameter sweep of an L-system tree (results in SQLite and
# CSV), a GreenLab plant simulated and reconstructed at three ages, and a mesh of one tree.
# It ends by saying where the reports are (Markdown and HTML). Usage: scripts/demo.sh [OUT]: the
# output goes to OUT, a folder that must not exist yet or be empty (default: demo-output in the
# checkout, replaced on every run).
set -euo pipefail
given="${1:-}"
if [ -n "$given" ]; then
  given="$(realpath -m "$given")"
  if [ -e "$given" ] && [ -n "$(ls -A "$given" 2> /dev/null)" ]; then
    echo "demo.sh: $given exists and is not empty; give a new or empty folder" >&2
    exit 2
  fi
fi
cd "$(dirname "$0")/.."
# ccache keys on paths relative to the checkout, so a fresh clone elsewhere (CI) reuses the cache.
export CCACHE_BASEDIR="$(pwd)"
# Debug builds would otherwise hash the build folder too (it is in their debug information).
export CCACHE_NOHASHDIR=true
scripts/deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)"
out="${given:-$(pwd)/demo-output}"
[ -n "$given" ] || rm -rf "$out"
mkdir -p "$out"
fspm=build/bin/fspm

echo "== adapted versus grown (Pirk 4.5.4), small version: 8 trees per type, age and set"
$fspm run examples/experiments/adapted_vs_grown.toml --replicates 8 --out "$out/adapted_vs_grown" --jobs "$(nproc)"
# Figures need an X display (VTK); without one, xvfb-run provides it. --html: the interactive
# report beside report.md (report/index.html).
if [ -n "${DISPLAY:-}" ]; then
  $fspm report "$out/adapted_vs_grown" --html --single-file
elif command -v xvfb-run > /dev/null; then
  xvfb-run -a $fspm report "$out/adapted_vs_grown" --html --single-file
else
  $fspm report "$out/adapted_vs_grown" --no-figures --html --single-file
fi

echo "== parameter sweep: Honda's monopodial tree (ABOP fig. 2.6), 36 runs"
$fspm run examples/experiments/branching.toml --out "$out/branching" --jobs "$(nproc)"
$fspm results show "$out/branching"
$fspm results export "$out/branching" --csv -o "$out/branching/results.csv"
$fspm report "$out/branching" --html

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
echo "demo output is in $out"
echo "report: $out/adapted_vs_grown/report.md (sweep: $out/branching/report.md)"
echo "HTML report: $out/adapted_vs_grown/report/index.html (sweep: $out/branching/report/index.html)"
