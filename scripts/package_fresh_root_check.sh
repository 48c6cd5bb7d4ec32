#!/usr/bin/env bash
# Installs a .deb made by scripts/package.sh on a fresh Debian 12 root and checks it there: a
# minimal root from debootstrap, `apt-get install ./fspm_VERSION_amd64.deb` alone (its Depends
# pull everything the commands and the Python module need), then `fspm --version`, `fspm-full`,
# `import fspm`, and examples/downstream built against the installed C++ package after installing
# a compiler, CMake and the headers the public headers include (scripts/downstream_check.sh).
# Needs root and a Debian mirror (FSPM_DEBIAN_MIRROR, default http://deb.debian.org/debian); takes
# minutes and downloads a few hundred MB, so scripts/test.sh does not run it (it runs
# scripts/package_check.sh, which unpacks the package with dpkg -x instead).
#   scripts/package_fresh_root_check.sh [DEB]     (default: the one in build-pkg/packages)
set -euo pipefail
cd "$(dirname "$0")/.."
[ "$(id -u)" -eq 0 ] || { echo "fresh_root_check: needs root (debootstrap, chroot)"; exit 1; }
deb=$(realpath "${1:-$(ls build-pkg/packages/fspm_*_amd64.deb | head -n 1)}")
version=$(dpkg-deb --field "$deb" Version)
mirror=${FSPM_DEBIAN_MIRROR:-http://deb.debian.org/debian}
if ! command -v debootstrap > /dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap > /dev/null
fi

root=$(mktemp -d /tmp/fspm-fresh-root.XXXXXX)
cleanup() {
  umount "$root/proc" 2> /dev/null || true
  umount "$root/dev" 2> /dev/null || true
  rm -rf --one-file-system "$root"
}
trap cleanup EXIT

echo "== debootstrap bookworm (minbase) into $root"
start=$(date +%s)
debootstrap --variant=minbase bookworm "$root" "$mirror" > "$root.debootstrap.log" 2>&1 \
  || { tail -n 30 "$root.debootstrap.log"; exit 1; }
rm -f "$root.debootstrap.log"
mount -t proc proc "$root/proc"
mount --bind /dev "$root/dev"
cp /etc/resolv.conf "$root/etc/resolv.conf"
in_root() { chroot "$root" env DEBIAN_FRONTEND=noninteractive LC_ALL=C.UTF-8 "$@"; }
echo "root made in $(($(date +%s) - start)) s"

echo "== apt-get install ./$(basename "$deb")"
cp "$deb" "$root/tmp/"
in_root apt-get update -qq
in_root apt-get install -y -qq "/tmp/$(basename "$deb")" > "$root/tmp/install.log" 2>&1 \
  || { tail -n 40 "$root/tmp/install.log"; exit 1; }
echo "installed with $(grep -c '^Setting up' "$root/tmp/install.log") packages set up"

printed=$(in_root fspm --version)
printed=${printed%%$'\n'*}  # the first line; the commit and features follow
[ "$printed" = "fspm $version" ] || { echo "fresh_root_check: fspm --version printed '$printed'"; exit 1; }
echo "fspm --version: $printed"
in_root fspm-full --version > /dev/null
in_root fspm tree info /usr/share/doc/fspm/examples/trees/small.nwk
in_root python3 -c "import fspm; assert fspm.__version__ == '$version'; print('import fspm', fspm.__version__, fspm.__file__)"
for page in fspm.1 fspm-grow.1 fspm-render.1; do
  in_root test -s "/usr/share/man/man1/$page" || { echo "fresh_root_check: no manual page $page"; exit 1; }
done
in_root test -s /usr/share/bash-completion/completions/fspm \
  || { echo "fresh_root_check: no bash completion"; exit 1; }
echo "manual pages and bash completion installed"
# Images go through OpenImageIO loaded on first use (libfspm_image_codec.so): a crown from the
# example photograph reads a PNG and writes its mask, and a render under the recommended Xvfb writes one.
in_root fspm-full crown /usr/share/doc/fspm/examples/crown/tree_front.png -o /tmp/crown_out/ > /dev/null
in_root test -s /tmp/crown_out/crown_mask.png || { echo "fresh_root_check: fspm crown wrote no mask"; exit 1; }
in_root xvfb-run -a fspm render /usr/share/doc/fspm/examples/trees/small.nwk -o /tmp/small.png > /dev/null
in_root python3 -c "import sys; sys.exit(0 if open('/tmp/small.png', 'rb').read(8) == b'\\x89PNG\\r\\n\\x1a\\n' else 'not a PNG')"
echo "an image read (fspm crown) and one written (xvfb-run fspm render)"

echo "== examples/downstream against /usr (compiler, CMake and the public headers' packages)"
in_root apt-get install -y -qq --no-install-recommends g++ make cmake pkg-config libeigen3-dev \
  libboost-dev nlohmann-json3-dev libtomlplusplus-dev > "$root/tmp/dev.log" 2>&1 \
  || { tail -n 40 "$root/tmp/dev.log"; exit 1; }
mkdir -p "$root/tmp/fspm/scripts" "$root/tmp/fspm/examples/trees" "$root/tmp/fspm/examples/greenlab"
cp scripts/downstream_check.sh "$root/tmp/fspm/scripts/"
cp -r examples/downstream "$root/tmp/fspm/examples/"
cp examples/trees/small.nwk "$root/tmp/fspm/examples/trees/"
cp examples/greenlab/leeuwenberg.toml "$root/tmp/fspm/examples/greenlab/"
in_root env FSPM_PREFIX=/usr /tmp/fspm/scripts/downstream_check.sh
echo "fresh_root_check: $(basename "$deb") installs and works on a fresh Debian 12 root" \
  "($(($(date +%s) - start)) s)"
