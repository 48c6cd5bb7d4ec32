#!/usr/bin/env bash
# Installs a build of fspm into a scratch prefix and builds examples/downstream against it from
# outside the source tree, once with find_package(fspm) and once with pkg-config, then runs both
# and checks their numbers against values known without fspm. Exits non-zero on any failure.
#   scripts/downstream_check.sh [BUILD_DIR]     (default: build)
# With FSPM_PREFIX set, uses that installed tree instead of installing BUILD_DIR (the package
# check points it at an unpacked .deb).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=${1:-build}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

if [ -n "${FSPM_PREFIX:-}" ]; then
  prefix=$FSPM_PREFIX
else
  prefix=$scratch/prefix
  cmake --install "$build" --prefix "$prefix" > "$scratch/install.log" \
    || { cat "$scratch/install.log"; exit 1; }
fi
# Every installed header compiles from the installed tree alone (with the include flags of the
# public dependencies): no public header includes an internal or uninstalled one.
headers=$(find "$prefix" -path '*/include/fspm' -type d | head -n 1)
(cd "$headers" && find . -name '*.hpp' | sed 's|^\./||' | sort | sed 's/.*/#include "&"/') > "$scratch/headers.cpp"
echo 'int main() { return 0; }' >> "$scratch/headers.cpp"
# shellcheck disable=SC2046  # pkg-config's flags are split into words on purpose
${CXX:-c++} -std=c++20 -fsyntax-only -I"$headers" $(pkg-config --cflags eigen3) "$scratch/headers.cpp" \
  || { echo "downstream: the installed headers do not compile on their own"; exit 1; }
echo "downstream: $(($(wc -l < "$scratch/headers.cpp") - 1)) installed headers compile from $headers"

# The example is copied out of the source tree so nothing can be found relative to it.
cp -r examples/downstream "$scratch/src"
cmake -S "$scratch/src" -B "$scratch/build" -DCMAKE_PREFIX_PATH="$prefix" > "$scratch/configure.log" 2>&1 \
  || { cat "$scratch/configure.log"; exit 1; }
grep "^-- fspm " "$scratch/configure.log"
cmake --build "$scratch/build" > "$scratch/build.log" 2>&1 || { cat "$scratch/build.log"; exit 1; }

libdir=$(dirname "$(find "$prefix" -name fspm.pc -path '*/pkgconfig/*' | head -n 1)")
# The run path finds shared fspm libraries (a package build) outside the system's folders.
# shellcheck disable=SC2046  # pkg-config's flags are split into words on purpose
PKG_CONFIG_PATH="$libdir" ${CXX:-c++} -O1 "$scratch/src/main.cpp" -o "$scratch/by_pkg_config" \
  $(PKG_CONFIG_PATH="$libdir" pkg-config --cflags --libs fspm) -Wl,-rpath,"$(dirname "$libdir")"

tree=$root/examples/trees/small.nwk
plant=$root/examples/greenlab/leeuwenberg.toml
for program in "$scratch/build/fspm_downstream" "$scratch/by_pkg_config"; do
  "$program" "$tree" "$plant" > "$scratch/out.txt"
  # small.nwk is ((1,2)3,(4,(5,6)7)8)9: nine nodes. Leeuwenberg's plant over 6 cycles: one growth
  # unit of 4 metamers, each unit bearing 3 the next cycle: 4 (1 + 3 + ... + 3^5) = 1456. A tree's
  # distance to itself is 0.
  for expected in "read_nodes 9" "greenlab_metamers 1456" "distance_read_read 0"; do
    grep -qx "$expected" "$scratch/out.txt" \
      || { cat "$scratch/out.txt"; echo "downstream: expected '$expected' from $program"; exit 1; }
  done
  grep -q "^distance_grown_greenlab [0-9]" "$scratch/out.txt" \
    || { cat "$scratch/out.txt"; echo "downstream: no distance from $program"; exit 1; }
done
cat "$scratch/out.txt"
echo "downstream: find_package(fspm) and pkg-config builds run against $prefix"
