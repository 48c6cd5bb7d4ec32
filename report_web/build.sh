#!/usr/bin/env bash
# Builds the browser files of the HTML report (fspm report --html) into OUT_DIR: the libraries
# from the npm registry at the versions of package-lock.json (npm ci), three.js bundled into one
# classic script, and the report's own script and style. Needs node and npm (scripts/deps.sh).
set -euo pipefail
out=${1:?usage: report_web/build.sh OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
# npm ci only when the installed packages are not those of the lockfile.
if ! cmp -s package-lock.json node_modules/.fspm-installed-lock.json 2> /dev/null; then
  npm ci --no-audit --no-fund --loglevel=error
  cp package-lock.json node_modules/.fspm-installed-lock.json
fi
mkdir -p "$out"
node_modules/.bin/esbuild src/three_entry.js --bundle --minify --format=iife \
  --legal-comments=none --log-level=warning --outfile="$out/three.min.js"
cp node_modules/plotly.js-cartesian-dist-min/plotly-cartesian.min.js "$out/plotly.min.js"
node_modules/.bin/esbuild node_modules/marked/lib/marked.umd.js --minify --legal-comments=none \
  --log-level=warning --outfile="$out/marked.min.js"
cp src/safe_markdown.js src/report.js src/report.css "$out/"
# The licences of what the report carries.
{
  for p in three plotly.js-cartesian-dist-min marked; do
    echo "== $p $(node -p "require('./node_modules/$p/package.json').version")"
    cat "node_modules/$p/LICENSE"* 2> /dev/null || true
    echo
  done
} > "$out/THIRD_PARTY_LICENSES.txt"
