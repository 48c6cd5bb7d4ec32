#!/usr/bin/env bash
# Installs what is missing, builds everything and runs every test: formatting, the main build
# (warnings as errors) with CTest, the installed C++ package used by examples/downstream, the
# Debian package unpacked and checked, a clang AddressSanitizer + UndefinedBehaviorSanitizer build
# of the core libraries with their tests and brief fuzzing, the Python tests when present, and the
# HTML report checked in headless Chromium.
# Exits non-zero on any failure; the output ends with the CTest summary of the main build.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache keys on paths relative to the checkout, so a fresh clone elsewhere (CI) reuses the cache.
export CCACHE_BASEDIR="$(pwd)"
# Debug builds would otherwise hash the build folder too (it is in their debug information).
export CCACHE_NOHASHDIR=true
root=$(pwd)
jobs=$(nproc)

echo "== dependencies"
scripts/deps.sh

echo "== clang-format check"
git ls-files '*.cpp' '*.hpp' | xargs -r clang-format --dry-run -Werror

echo "== benchmark table check (every benchmark in bench/ has a row in docs/BENCHMARKS.md)"
/usr/bin/python3 scripts/bench_table.py --check

echo "== sanitizer build (clang, ASan + UBSan, core libraries and fuzz targets)"
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="-O1" -DFSPM_CORE_ONLY=ON -DFSPM_SANITIZE=ON -DFSPM_FUZZ=ON \
  -DFSPM_BUILD_BENCH=OFF -DFSPM_WERROR=OFF > build-asan.log 2>&1 || { cat build-asan.log; exit 1; }
cmake --build build-asan -j "$jobs"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j "$jobs" > build-asan-ctest.log 2>&1 \
  || { grep -v "^ *#[0-9]" build-asan-ctest.log | tail -n 150; exit 1; }
tail -n 3 build-asan-ctest.log
for fuzzer in build-asan/bin/fspm_*_fuzz; do
  [ -x "$fuzzer" ] || continue
  name=$(basename "$fuzzer")
  corpus="fuzz/corpus/${name#fspm_}"
  work=$(mktemp -d)
  [ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
  echo "fuzzing $name for 20 s"
  "$fuzzer" -max_total_time=20 -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len=4096 "$work" > "$work.log" 2>&1 \
    || { tail -n 40 "$work.log"; exit 1; }
  rm -rf "$work" "$work.log"
done

echo "== main build (Release, warnings as errors)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 \
  || { cat build.log; exit 1; }
grep -E "^-- fspm:" build.log || true
cmake --build build -j "$jobs"

echo "== installed C++ package: examples/downstream built against it (find_package, pkg-config)"
scripts/downstream_check.sh build

echo "== Debian package (scripts/package.sh: shared libraries, in build-pkg), unpacked and checked"
scripts/package.sh build-pkg > build-pkg.package.log 2>&1 || { cat build-pkg.package.log; exit 1; }
tail -n 1 build-pkg.package.log
scripts/package_check.sh "$(tail -n 1 build-pkg.package.log)"

if [ -f build/python/fspm/__init__.py ]; then
  export PYTHONPATH="$root/build/python"
  echo "== Python tests (pytest)"
  /usr/bin/python3 -m pytest -q -p no:cacheprovider python/tests
  echo "== notebooks (executed top to bottom)"
  for nb in notebooks/*.ipynb; do
    [ -f "$nb" ] || continue
    /usr/bin/python3 -m nbconvert --to notebook --execute --ExecutePreprocessor.timeout=600 \
      --output-dir build/notebooks "$nb" > build/nbconvert.log 2>&1 \
      || { tail -n 60 build/nbconvert.log; echo "notebook $nb failed"; exit 1; }
    echo "executed $nb"
  done
  # The quickstart shows its plots inline (and saves them): four figures embedded in the output.
  /usr/bin/python3 -c "import json, sys; nb = json.load(open('build/notebooks/quickstart.ipynb'));
n = sum('image/png' in o.get('data', {}) for c in nb['cells'] for o in c.get('outputs', []));
sys.exit(0 if n >= 4 else f'quickstart.ipynb shows {n} plots inline, expected 4')"
fi

echo "== README.md and the docs pages' commands, run as written in a clean clone"
/usr/bin/python3 scripts/readme_check.py --bin build/bin --timings build/readme_timings.json

echo "== HTML report in headless Chromium (fspm report --html)"
scripts/html_report_check.sh

echo "== CTest (main build, under Xvfb so renders and the viewer are tested)"
xvfb-run -a -s "-screen 0 1280x1024x24" ctest --test-dir build --output-on-failure -j "$jobs"
