#!/usr/bin/env bash
# Makes the Debian package fspm_VERSION_amd64.deb with CPack (cmake/FspmPackaging.cmake): the fspm
# and fspm-full commands, the modules as shared libraries (SONAME libfspm_MODULE.so.MAJOR.MINOR,
# with a shlibs file), headers, CMake package and pkg-config file, the Python module (in
# /usr/lib/python3/dist-packages/fspm), docs and examples. Depends is computed by dpkg-shlibdeps
# from the shared libraries the executables, libraries and Python module use.
#   scripts/package.sh [BUILD_DIR]     (default: build-pkg)
# The build folder is configured with FSPM_SHARED_LIBS=ON and without tests and benchmarks; with
# a warm ccache it compiles nothing the main build compiled. Prints the path of the .deb last.
# Check it with scripts/package_check.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
CCACHE_BASEDIR=$(pwd)
export CCACHE_BASEDIR CCACHE_NOHASHDIR=true
build=${1:-build-pkg}

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFSPM_SHARED_LIBS=ON \
  -DFSPM_PYTHON_INSTALL_DIR=lib/python3/dist-packages -DFSPM_BUILD_TESTS=OFF -DFSPM_BUILD_BENCH=OFF > "$build.log" 2>&1 || { cat "$build.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"
rm -f "$build"/packages/fspm_*.deb
(cd "$build" && cpack -G DEB > cpack.log 2>&1) || { cat "$build/cpack.log"; exit 1; }
deb=$(ls "$build"/packages/fspm_*_amd64.deb)
dpkg-deb --field "$deb" Package Version Depends
echo "$deb"
