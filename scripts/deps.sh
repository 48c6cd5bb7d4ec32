#!/usr/bin/env bash
# Installs the Debian 12 packages fspm builds and tests with. Idempotent: packages already
# present are skipped, and nothing runs apt-get when all are there.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build ccache pkg-config git clang clang-format libclang-rt-14-dev
  # core and modules
  libeigen3-dev libceres-dev libboost-dev libboost-graph-dev libboost-math-dev libglm-dev
  libsqlite3-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libspdlog-dev libfmt-dev
  libtbb-dev libgtest-dev libgmock-dev libbenchmark-dev
  # SIMD light kernels with run-time target dispatch (Google Highway)
  libhwy-dev
  # scans: nanoflann for the neighbour graph of point sets, CGAL for the alpha-shape cluster hulls,
  # assimp for glTF 2.0 mesh input (.gltf, .glb)
  libnanoflann-dev libcgal-dev libassimp-dev
  # graphics (optional parts: VTK renders, the viewer, image output)
  libvtk9-dev libopenimageio-dev openimageio-tools python3-imath libglfw3-dev libgl-dev libglx-mesa0 libgl1-mesa-dri xvfb xauth
  # the viewer's controls panel: Dear ImGui (a static library with its GLFW and OpenGL 3 back ends)
  libimgui-dev
  # HTML report (fspm report --html): zlib gzips its trees; chromium checks it in tests (node and
  # npm, which install its browser libraries from the npm registry at build time, see below)
  zlib1g-dev chromium
  # distributed runs
  libopenmpi-dev openmpi-bin
  # Python module, tests and notebooks (Debian's python3 only)
  python3 python3-dev pybind11-dev python3-numpy python3-pytest python3-pandas python3-scipy
  python3-pip python3-setuptools python3-wheel python3-venv
  python3-matplotlib python3-nbconvert python3-nbformat python3-ipykernel jupyter-nbconvert
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# node and npm by command, not by package: a machine may have Node.js from another source (whose
# nodejs package conflicts with Debian's npm); Debian's are installed only when either is missing.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  missing+=(nodejs npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "deps: installing ${#missing[@]} missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "deps: done"
