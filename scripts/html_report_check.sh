#!/usr/bin/env bash
# The HTML report in a real browser: runs a small version of the adapted-versus-grown experiment
# (4 trees per type, age and set), writes its HTML report, opens it from file:// in headless
# Chromium (report_web/test/check_report.mjs: no console error, every plot and 3D view drawn, a
# table sorts, the light profile plot shows the numbers of data.js) and compares the page's numbers with results.sqlite and ttests.csv
# (report_web/test/check_numbers.py). Then the report of an experiment whose name, description and
# comparison names carry script (report_web/test/hostile_experiment.toml) must run none of it
# (report_web/test/check_hostile.mjs). Needs a Release build in build/ and scripts/deps.sh.
#   scripts/html_report_check.sh [SCREENSHOT.png]   (default build/html-report-check/page.png)
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/html-report-check
shot=${1:-$out/page.png}
rm -rf "$out/avg" "$out/hostile"
mkdir -p "$out"
build/bin/fspm run examples/experiments/adapted_vs_grown.toml --replicates 4 --out "$out/avg" \
  --jobs "$(nproc)" --json > "$out/run.json"
build/bin/fspm report "$out/avg" --html --no-figures
# puppeteer-core, pinned by report_web/package-lock.json (the build installs it with npm ci).
(cd report_web && [ -d node_modules/puppeteer-core ] || npm ci --no-audit --no-fund --loglevel=error)
node report_web/test/check_report.mjs "$out/avg/report/index.html" "$shot" "$out/tables.json"
python3 report_web/test/check_numbers.py "$out/avg" "$out/tables.json"
build/bin/fspm run report_web/test/hostile_experiment.toml --out "$out/hostile" -q
build/bin/fspm report "$out/hostile" --html --no-figures -q
node report_web/test/check_hostile.mjs "$out/hostile/report/index.html"
du -sh "$out/avg/report"
