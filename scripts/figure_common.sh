# shellcheck shell=bash
# The start the figure scripts share, sourced after `set -euo pipefail` with the script's own
# arguments: checks for FSPM_BINARY OUTPUT.png (the usage line adds $figure_usage_tail, the
# script's further arguments) and sets fspm, out, a scratch folder $work removed on exit and the
# caption $font (FONT overrides it).
if [[ $# -lt 2 ]]; then
  echo "usage: $0 FSPM_BINARY OUTPUT.png${figure_usage_tail:-}" >&2
  exit 2
fi
fspm=$1
out=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
font=${FONT:-/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf}
