#!/usr/bin/env bash
# The main job: installs what is missing, builds Release and runs a small end-to-end example,
# then says where its output is.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j "$(nproc)"
out=demo-output
mkdir -p "$out"
fspm=build/bin/fspm

echo "== a Newick tree converted to every format"
$fspm tree convert examples/trees/small.nwk "$out/small.tree"
$fspm tree convert "$out/small.tree" "$out/small.treeb"
$fspm tree convert "$out/small.treeb" "$out/small.mtg"
$fspm tree info "$out/small.treeb"

echo
echo "demo output is in $(pwd)/$out"
