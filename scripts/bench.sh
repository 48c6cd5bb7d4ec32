#!/usr/bin/env bash
# Builds Release and runs every benchmark in bench/, printing the results as one JSON document
# per benchmark program (Google Benchmark's format) on stdout. Pass a regex to filter programs.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache keys on paths relative to the checkout, so a fresh clone elsewhere (CI) reuses the cache.
export CCACHE_BASEDIR="$(pwd)"
# Debug builds would otherwise hash the build folder too (it is in their debug information).
export CCACHE_NOHASHDIR=true
filter="${1:-.}"
scripts/deps.sh >&2
cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DFSPM_BUILD_TESTS=OFF \
  -DFSPM_WITH_PYTHON=OFF >&2
cmake --build build-bench -j "$(nproc)" >&2
echo "["
first=1
for b in build-bench/bin/fspm_*_bench; do
  [[ "$(basename "$b")" =~ $filter ]] || continue
  [ $first -eq 1 ] || echo ","
  first=0
  "$b" --benchmark_format=json 2>/dev/null
done
echo "]"
