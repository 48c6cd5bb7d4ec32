#!/usr/bin/env bash
# Checks a .deb made by scripts/package.sh without installing it on this machine: apt-get
# simulates installing it (every Depends resolvable from Debian), dpkg -x unpacks it into a
# scratch root, every executable and the Python module find all their shared libraries, fspm
# --version gives the package's version, fspm-full runs, `import fspm` works from the unpacked
# dist-packages, the manual pages (fspm.1 and one per command of fspm --help) and the bash
# completion are in the package and fspm.1 formats without a warning, and examples/downstream builds against the unpacked C++ package and gives the
# known numbers (scripts/downstream_check.sh). Exits non-zero on any failure.
#   scripts/package_check.sh [DEB]     (default: the one in build-pkg/packages)
set -euo pipefail
cd "$(dirname "$0")/.."
deb=${1:-$(ls build-pkg/packages/fspm_*_amd64.deb | head -n 1)}
deb=$(realpath "$deb")
version=$(dpkg-deb --field "$deb" Version)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

echo "== $deb: apt-get install --simulate"
apt-get install --simulate "$deb" > "$scratch/apt.log" 2>&1 || { cat "$scratch/apt.log"; exit 1; }
grep -E "^(Inst|Conf) fspm " "$scratch/apt.log" | head -n 1 \
  || { cat "$scratch/apt.log"; echo "package_check: apt would not install fspm"; exit 1; }

echo "== unpacked into $scratch/root"
root=$scratch/root
dpkg -x "$deb" "$root"
for f in "$root"/usr/bin/* "$root"/usr/lib/python3/dist-packages/fspm/_fspm*.so; do
  if ldd "$f" | grep -q "not found"; then
    ldd "$f" | grep "not found"
    echo "package_check: $f misses shared libraries"
    exit 1
  fi
done

printed=$("$root/usr/bin/fspm" --version)
printed=${printed%%$'\n'*}  # the first line; the commit and features follow
[ "$printed" = "fspm $version" ] \
  || { echo "package_check: fspm --version printed '$printed', the package is $version"; exit 1; }
echo "fspm --version: $printed"
"$root/usr/bin/fspm-full" --version > /dev/null
"$root/usr/bin/fspm" tree info "$root/usr/share/doc/fspm/examples/trees/small.nwk" > /dev/null

echo "== manual pages and bash completion"
man1=$root/usr/share/man/man1
[ -f "$man1/fspm.1" ] || { echo "package_check: no usr/share/man/man1/fspm.1"; exit 1; }
for command in $("$root/usr/bin/fspm" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && NF {print $1}'); do
  [ -f "$man1/fspm-$command.1" ] || { echo "package_check: no manual page fspm-$command.1"; exit 1; }
done
completion=$root/usr/share/bash-completion/completions/fspm
grep -q "^complete .* fspm" "$completion" \
  || { echo "package_check: no bash completion for fspm in $completion"; exit 1; }
# man-db and groff-base are in Debian's standard install; without them the roff structure is
# checked. groff -ww prints a warning for a malformed page.
if command -v man > /dev/null && command -v groff > /dev/null; then
  warnings=$(groff -man -ww -z "$man1/fspm.1" 2>&1)
  [ -z "$warnings" ] || { echo "package_check: fspm.1: $warnings"; exit 1; }
  man -l "$man1/fspm.1" 2> /dev/null | grep -q "^NAME" \
    || { echo "package_check: man -l cannot format fspm.1"; exit 1; }
  echo "man -l fspm.1: $(man -l "$man1/fspm.1" 2> /dev/null | sed -n '/^NAME/{n;p;q}' | sed 's/^ *//')"
else
  grep -q "^\.TH FSPM 1" "$man1/fspm.1" && grep -q "^\.SH NAME" "$man1/fspm.1" \
    || { echo "package_check: fspm.1 lacks .TH or .SH NAME"; exit 1; }
fi

PYTHONPATH="$root/usr/lib/python3/dist-packages" /usr/bin/python3 -c \
  "import fspm, sys; assert fspm.__file__.startswith(sys.argv[1]), fspm.__file__; print('import fspm:', fspm.__file__)" \
  "$root"

echo "== examples/downstream against the unpacked package"
FSPM_PREFIX="$root/usr" scripts/downstream_check.sh
echo "package_check: $deb passed"
