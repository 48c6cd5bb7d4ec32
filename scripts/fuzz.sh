#!/usr/bin/env bash
# Runs every libFuzzer target of the sanitizer build for longer than scripts/test.sh does, from
# its corpus in fuzz/corpus/, under the same memory limit: scripts/fuzz.sh [SECONDS per target,
# default 300] [TARGET name filter]. Needs the build-asan folder scripts/test.sh makes. Crashes
# are kept as build-asan/fuzz-findings/<target>/crash-* and the script exits 1.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-300}
filter=${2:-}
status=0
for fuzzer in build-asan/bin/fspm_*_fuzz; do
  [ -x "$fuzzer" ] || { echo "no fuzz targets: run scripts/test.sh first" >&2; exit 1; }
  name=$(basename "$fuzzer")
  [[ -z "$filter" || "$name" == *"$filter"* ]] || continue
  corpus="fuzz/corpus/${name#fspm_}"
  work=$(mktemp -d)
  findings="build-asan/fuzz-findings/$name"
  mkdir -p "$findings"
  [ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
  echo "fuzzing $name for $seconds s"
  if ! ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      "$fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=1024 \
      -max_len=4096 -artifact_prefix="$findings/" "$work" > "$findings/log.txt" 2>&1; then
    tail -n 30 "$findings/log.txt"
    status=1
  fi
  rm -rf "$work"
done
exit $status
