#!/usr/bin/env bash
# Hostile audit of the command line: runs every command on wrong, broken and adversarial input as
# an attacker or a careless user would, and reports each case that breaks a rule:
#   - no crash: the exit code is 0 or 1 (143 after SIGTERM, 130 after SIGINT), never 2 (an
#     internal error) or another signal;
#   - no hang: every case ends within TIMEOUT seconds;
#   - the memory budget holds: the peak resident memory stays below --memory-limit (LIMIT_MIB)
#     plus SLACK_MIB for the program's code and libraries;
#   - nothing left behind: a failed command leaves no new file and no temporary;
#   - messages: a failure prints one line "fspm: error: ..." naming the input or output at fault;
#     no count is printed as the 18446744073709551615 of a saturated 64-bit count.
# The cases: every input kind broken in fifteen ways through each command that reads it, FIFOs
# where secondary inputs go, a key given twice in each TOML and JSON kind, headers that lie (PLY,
# PCD, LAS, glTF, GLB, images, tree files), growth past any memory, every writer and standard
# output on /dev/full, wrong options and every numeric option at 1e308, 1e-320 and 2^63, jobs
# sharing the memory limit, counts in plant files past any memory, nan and 1e309 in view and MTG
# files, inputs that draw nothing, control characters in file names, and signals in mid-run.
#
# Usage: scripts/hostile_audit.sh [FSPM]   (default build/bin/fspm; env LIMIT_MIB, SLACK_MIB,
# TIMEOUT, KEEP=1 keeps the scratch folder, VERBOSE=1 prints every case's exit, memory and
# error). Prints one line per finding and a summary; exits 1 when there is a finding.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
FSPM=$(realpath "${1:-$here/build/bin/fspm}")
LIMIT_MIB=${LIMIT_MIB:-256}
SLACK_MIB=${SLACK_MIB:-256}
TIMEOUT=${TIMEOUT:-60}
ex=$here/examples
work=$(mktemp -d /tmp/fspm_hostile.XXXXXX)
[ "${KEEP:-0}" = 1 ] || trap 'rm -rf "$work"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
[ -x "$FSPM" ] || { echo "hostile_audit: no executable $FSPM" >&2; exit 2; }

cases=0
findings=0
started=$(date +%s)
max_rss_kib=0

finding() {  # CASE WHAT
  findings=$((findings + 1))
  printf 'FINDING %s: %s\n' "$1" "$2"
}

# run_case NAME EXPECT NAMED SETUP ARGS
#   EXPECT: fail (exit 1), ok (exit 0) or any (0 or 1); NAMED: a text the error must contain
#   (the file at fault; empty: not checked); SETUP: shell run first in the case's folder;
#   ARGS: the fspm arguments (words split by the shell, run in the case's folder).
run_case() {
  local name=$1 expect=$2 named=$3 setup=$4 args=$5
  cases=$((cases + 1))
  local dir=$work/c$cases
  mkdir -p "$dir"
  (cd "$dir" && eval "$setup") >/dev/null 2>&1
  local before
  before=$(cd "$dir" && find . -mindepth 1 | sort)
  (
    cd "$dir" || exit 99
    # Through eval: ARGS may quote words and redirect stdout (after ours, so theirs wins).
    eval "exec /usr/bin/time -f '%M' -o .rss timeout -s KILL $TIMEOUT \"\$FSPM\"" \
      "--memory-limit ${LIMIT_MIB}M >.out 2>.err </dev/null $args"
  )
  local rc=$?
  local rss
  rss=$(tail -n 1 "$dir/.rss" 2>/dev/null | tr -dc '0-9')
  rss=${rss:-0}
  # time writes "Command exited with non-zero status N" before the figure; a kill: "Command
  # terminated by signal 9".
  if grep -q 'terminated by signal 9' "$dir/.rss" 2>/dev/null; then rc=137; fi
  [ "$rss" -gt "$max_rss_kib" ] && max_rss_kib=$rss
  local err
  err=$(head -c 2000 "$dir/.err")
  local lines
  lines=$(grep -c '' "$dir/.err")
  if [ "$rc" -eq 137 ]; then
    finding "$name" "no answer within ${TIMEOUT} s (killed): $args"
  elif [ "$rc" -eq 2 ] || [ "$rc" -gt 1 ]; then
    finding "$name" "exit $rc: $args: $(head -n 1 "$dir/.err")"
  fi
  if [ "$rss" -gt $(((LIMIT_MIB + SLACK_MIB) * 1024)) ]; then
    finding "$name" "peak resident memory $((rss / 1024)) MiB over the limit of ${LIMIT_MIB} MiB: $args"
  fi
  if [ "$rc" -eq 1 ]; then
    [ "$expect" = ok ] && finding "$name" "failed: $args: $err"
    # Log lines ([info], [warning]) may come first; then one line of error, and nothing else.
    local other
    other=$(grep -v -c -E '^\[(info|warning|debug)\] |^fspm: error: ' "$dir/.err")
    if [ "$other" -ne 0 ] || [ "$(grep -c '^fspm: error: ' "$dir/.err")" -ne 1 ]; then
      finding "$name" "not one 'fspm: error:' line ($lines lines): $(grep -v '^\[' "$dir/.err" | head -n 1)"
    fi
    if [ -n "$named" ] && [[ $err != *"$named"* ]]; then
      finding "$name" "the message does not name $named: $err"
    fi
    local after
    after=$(cd "$dir" && find . -mindepth 1 ! -name .out ! -name .err ! -name .rss | sort)
    local extra
    extra=$(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')
    [ -n "$extra" ] && finding "$name" "left behind after a failure: $extra"
  elif [ "$rc" -eq 0 ] && [ "$expect" = fail ]; then
    finding "$name" "accepted (exit 0): $args"
  fi
  # A count that saturated at 2^64 - 1 is written "more than 10^19", never as that number.
  if grep -q 18446744073709551615 "$dir/.out" "$dir/.err" 2>/dev/null; then
    finding "$name" "prints the saturated count 18446744073709551615: $args"
  fi
  local tmp
  tmp=$(cd "$dir" && find . -name '*.tmp*' | head -n 3 | tr '\n' ' ')
  [ -n "$tmp" ] && finding "$name" "temporary files left: $tmp"
  if [ "${VERBOSE:-0}" = 1 ]; then
    printf 'case %s: exit %s, %s MiB: %s\n' "$name" "$rc" "$((rss / 1024))" \
      "$(grep '^fspm: error: ' "$dir/.err" | head -c 200)"
  fi
  rm -rf "$dir"
}

# run_signal NAME SIGNAL CODE ARGS: starts ARGS, sends SIGNAL after a second, expects exit CODE
# and no temporary or partial output (OUT, when given, must not exist).
run_signal() {
  local name=$1 sig=$2 code=$3 out=$4 args=$5
  cases=$((cases + 1))
  local dir=$work/c$cases
  mkdir -p "$dir"
  (
    cd "$dir" || exit 99
    eval "\"\$FSPM\" --memory-limit ${LIMIT_MIB}M >.out 2>.err </dev/null $args &"
    local pid=$!
    sleep 1
    kill -s "$sig" "$pid" 2>/dev/null
    local waited=0
    while kill -0 "$pid" 2>/dev/null && [ $waited -lt "$TIMEOUT" ]; do
      sleep 1
      waited=$((waited + 1))
    done
    if kill -0 "$pid" 2>/dev/null; then
      kill -s KILL "$pid"
      wait "$pid"
      exit 137
    fi
    wait "$pid"
  )
  local rc=$?
  if [ "$rc" -eq 137 ]; then
    finding "$name" "did not stop within ${TIMEOUT} s of SIG$sig: $args"
  elif [ "$rc" -eq 1 ] && grep -q '(--memory-limit)$' "$dir/.err"; then
    :  # refused by the memory limit before the signal came (a small LIMIT_MIB)
  elif [ "$rc" -ne "$code" ] && [ "$rc" -ne 0 ]; then
    finding "$name" "exit $rc after SIG$sig (expected $code, or 0 when done first): $args"
  fi
  if [ "$rc" -ne 0 ] && [ -n "$out" ] && [ -e "$dir/$out" ]; then
    finding "$name" "partial output $out after SIG$sig"
  fi
  local tmp
  tmp=$(cd "$dir" && find . -name '*.tmp*' | head -n 3 | tr '\n' ' ')
  [ -n "$tmp" ] && finding "$name" "temporary files left after SIG$sig: $tmp"
  rm -rf "$dir"
}

# --- valid inputs, made once -----------------------------------------------------------------
v=$work/valid
mkdir -p "$v"
cp "$ex/trees/small.nwk" "$v/v.nwk"
cp "$ex/trees/open_a12.treeb" "$v/v.treeb"
cp "$ex/trees/growth_units.mtg" "$v/v.mtg"
cp "$ex/trees/y_tubes.obj" "$v/v.obj"
cp "$ex/scans/ahn4_tree_121922_487459.las" "$v/v.las"
cp "$ex/lsystems/abop_1_24a.l" "$v/v.l"
cp "$ex/environment/tree_a.toml" "$v/growth.toml"
cp "$ex/greenlab/gl1_plant.toml" "$v/plant.toml"
cp "$ex/environment/wall_scene.json" "$v/scene.json"
cp "$ex/environment/points.csv" "$v/points.csv"
cp "$ex/crown/tree_front.png" "$v/v.png"
cp "$ex/stats/plant_growth_ctrl.csv" "$v/a.csv"
printf '[experiment]\nname = "s"\n[model]\nkind = "synthetic"\n' >"$v/experiment.toml"
q() { "$FSPM" -q "$@" >/dev/null 2>&1 || echo "hostile_audit: setup failed: fspm $*" >&2; }
q tree convert "$v/v.nwk" "$v/v.tree"
q greenlab simulate "$v/plant.toml" -o "$v/v.ctree"
q scan "$v/v.treeb" -o "$v/v.ply" --density 2000
q scan "$v/v.treeb" -o "$v/v.xyz" --density 2000
q mesh "$v/v.mtg" -o "$v/v.glb"  # a Newick without branch lengths draws nothing
q encode "$v/v.treeb" -o "$v/v.clusters"
q run "$v/experiment.toml" --out "$v/results"
{ pcd_n=$(grep -c '' "$v/v.xyz")
  printf 'VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %s\nHEIGHT 1\nPOINTS %s\nDATA ascii\n' "$pcd_n" "$pcd_n"
  cat "$v/v.xyz"; } >"$v/v.pcd"
# A glTF of one triangle, its buffer inline.
printf '%s' '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' >"$v/v.gltf"
q tree convert "$v/v.nwk" "$v/v2.mtg"
cp "$ex/lsystems/monopodial_tree.l" "$v/m.l"
cp "$ex/lsystems/monopodial_tree.v" "$v/m.v" 2>/dev/null || printf 'angle factor: 30\n' >"$v/m.v"
# An experiment whose runs keep their trees and compare them, for fspm compare.
printf '[experiment]\nname = "c"\nreplicates = 3\n[model]\nkind = "synthetic"\n[sweep]\nnodes = [2, 6]\n[outputs]\nkeep = ["tree"]\n[[comparison]]\nname = "2-6"\na = { nodes = 2 }\nb = { nodes = 6 }\n' >"$v/compare.toml"
q run "$v/compare.toml" --out "$v/cmp"

# --- hostile variants of each input kind, through each command that reads it ---------------
# input_cases NAME FILE EXT CMD: CMD holds @IN where the input goes. A text format cut in half
# may still be a valid, shorter file (a TOML file cut between two lines): its truncation may pass.
input_cases() {
  local label=$1 valid=$2 ext=$3 cmd=$4
  local cut=fail
  case $ext in toml | csv | l | xyz | obj) cut=any ;; esac
  local f=in.$ext
  local base
  base=${cmd//@IN/$f}
  run_case "$label/empty" fail "$f" ": > $f" "$base"
  run_case "$label/garbage" fail "$f" "head -c 3000 /bin/ls > $f" "$base"
  run_case "$label/garbage-text" fail "$f" "base64 /bin/ls | head -c 3000 > $f" "$base"
  run_case "$label/truncated" "$cut" "$f" \
    "head -c \$((\$(stat -c %s $valid) / 2)) $valid > $f" "$base"
  run_case "$label/one-byte" fail "$f" "head -c 1 $valid > $f" "$base"
  run_case "$label/nul-bytes" fail "$f" "head -c 4096 /dev/zero > $f" "$base"
  run_case "$label/directory" fail "$f" "mkdir $f" "$base"
  run_case "$label/missing" fail "$f" ":" "$base"
  run_case "$label/dangling-link" fail "$f" "ln -s nowhere.$ext $f" "$base"
  run_case "$label/link-loop" fail "$f" "ln -s $f $f" "$base"
  run_case "$label/unreadable" any "" "cp $valid $f; chmod 000 $f" "$base"
  run_case "$label/link-to-valid" any "" "ln -s $valid $f" "$base"
  local other=$v/v.png
  [ "$ext" = png ] && other=$v/v.ply
  run_case "$label/wrong-extension" fail "" "cp $other $f" "$base"
  run_case "$label/device" fail "$f" "ln -s /dev/zero $f" "$base"
  # A FIFO fed with the valid file: read like a pipe, or refused as not a regular file; never
  # waiting for ever. The writer is stopped with the case.
  run_case "$label/fifo" any "" \
    "mkfifo $f; (timeout 20 sh -c 'cat $valid > $f' &)" "$base"
}

input_cases tree-info-nwk "$v/v.nwk" nwk "tree info @IN"
input_cases tree-info-tree "$v/v.tree" tree "tree info @IN"
input_cases tree-info-treeb "$v/v.treeb" treeb "tree info @IN"
input_cases tree-info-mtg "$v/v.mtg" mtg "tree info @IN"
input_cases tree-convert-treeb "$v/v.treeb" treeb "tree convert @IN out.tree"
input_cases tree-convert-glb "$v/v.glb" glb "tree convert @IN out.tree"
input_cases distance-nwk "$v/v.nwk" nwk "distance @IN $v/v.nwk"
input_cases stages-treeb "$v/v.treeb" treeb "stages @IN --at 0.5 -o out.tree"
input_cases stages-obj "$v/v.obj" obj "stages @IN --at 0.5 -o out.tree"
input_cases scan-tree "$v/v.tree" tree "scan @IN -o out.xyz"
input_cases encode-xyz "$v/v.xyz" xyz "encode @IN -o out.clusters"
input_cases encode-ply "$v/v.ply" ply "encode @IN -o out.clusters"
input_cases encode-las "$v/v.las" las "encode @IN -o out.clusters"
input_cases encode-glb "$v/v.glb" glb "encode @IN -o out.clusters"
input_cases decode-clusters "$v/v.clusters" clusters "decode @IN -o out.tree"
input_cases reconstruct-ctree "$v/v.ctree" ctree "greenlab reconstruct @IN -o out.tree"
input_cases simulate-toml "$v/plant.toml" toml "greenlab simulate @IN -o out.ctree"
input_cases grow-toml "$v/growth.toml" toml "grow @IN -o out.tree"
input_cases derive-l "$v/v.l" l "lsystem derive @IN"
input_cases interpret-l "$v/v.l" l "lsystem interpret @IN -o out.tree"
input_cases light-scene "$v/scene.json" json "light --scene @IN --points $v/points.csv"
input_cases light-points "$v/points.csv" csv "light --scene $v/scene.json --points @IN"
input_cases run-experiment "$v/experiment.toml" toml "run @IN --out out"
input_cases mesh-treeb "$v/v.treeb" treeb "mesh @IN -o out.obj"
input_cases mesh-scene "$v/scene.json" json "mesh @IN -o out.glb"
input_cases crown-png "$v/v.png" png "crown @IN -o out"
input_cases ttest-csv "$v/a.csv" csv "stats ttest @IN $v/a.csv"
input_cases encode-pcd "$v/v.pcd" pcd "encode @IN -o out.clusters"
input_cases encode-gltf "$v/v.gltf" gltf "encode @IN -o out.clusters"
input_cases render-xyz "$v/v.xyz" xyz "render @IN -o out.png"
input_cases mesh-ctree "$v/v.ctree" ctree "mesh @IN -o out.glb"
input_cases mesh-l "$v/v.l" l "mesh @IN -o out.glb"
input_cases tree-convert-mtg "$v/v2.mtg" mtg "tree convert @IN out.tree"
input_cases distance-second-treeb "$v/v.treeb" treeb "distance $v/v.nwk @IN"
input_cases adapt-scene "$v/scene.json" json "adapt $v/v.treeb --scene @IN -o out.tree"
input_cases grow-scene "$v/scene.json" json "grow $v/growth.toml --scene @IN -o out.tree"
input_cases crown-mask "$v/v.png" png "crown $v/v.png --mask @IN -o out"
# A view file is read leniently (docs: unknown keys are ignored, cpfg has many display settings),
# so only what cannot be a view file's text is expected refused.
for kind in "missing:" "directory:mkdir in.v" "device:ln -s /dev/zero in.v" "link-loop:ln -s in.v in.v" \
  "binary:head -c 3000 /bin/ls > in.v" "nul-bytes:head -c 4096 /dev/zero > in.v"; do
  run_case "interpret-view/${kind%%:*}" fail in.v "${kind#*:}" "lsystem interpret $v/m.l --view in.v -o out.tree"
done
run_case interpret-view/bad-number fail in.v "printf 'angle factor: x\n' > in.v" "lsystem interpret $v/m.l --view in.v -o out.tree"
run_case interpret-view/angle-factor-0 fail in.v "printf 'angle factor: 0\n' > in.v" "lsystem interpret $v/m.l --view in.v -o out.tree"
input_cases describe-csv "$v/a.csv" csv "stats describe @IN"

# --- headers that declare far more than the file holds ---------------------------------------
ply_header() {  # COUNT FORMAT
  printf 'ply\nformat %s 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\nend_header\n' "$2" "$1"
}
run_case header/ply-binary fail big.ply "$(declare -f ply_header); { ply_header 1000000000000 binary_little_endian; head -c 24 /dev/zero; } > big.ply" \
  "encode big.ply -o out.clusters"
run_case header/ply-ascii fail big.ply "$(declare -f ply_header); { ply_header 4000000000 ascii; echo 0 0 0; } > big.ply" \
  "encode big.ply -o out.clusters"
run_case header/ply-negative fail big.ply "$(declare -f ply_header); { ply_header -5 ascii; echo 0 0 0; } > big.ply" \
  "encode big.ply -o out.clusters"
run_case header/pcd fail big.pcd \
  "printf 'VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4000000000\nHEIGHT 1\nPOINTS 4000000000\nDATA binary\n' > big.pcd; head -c 12 /dev/zero >> big.pcd" \
  "encode big.pcd -o out.clusters"
run_case header/tree-nodes fail big.tree "printf 'fspm-tree 1\nnodes 4000000000\n0 - internode 1 0 0 0 0 0 0 1 0 0 1 1 0.1 0\n' > big.tree" \
  "tree info big.tree"
run_case header/treeb-count fail big.treeb "head -c 16 $v/v.treeb > big.treeb; printf '\377\377\377\377\377\377\377\177' >> big.treeb; head -c 64 /dev/zero >> big.treeb" \
  "tree info big.treeb"
run_case header/ctree-count fail big.ctree "head -c 12 $v/v.ctree > big.ctree; printf '\377\377\377\377' >> big.ctree; head -c 64 /dev/zero >> big.ctree" \
  "greenlab reconstruct big.ctree -o out.tree"
run_case header/clusters-count fail big.clusters "head -c 40 $v/v.clusters > big.clusters; printf '\377\377\377\377' >> big.clusters; head -c 64 /dev/zero >> big.clusters" \
  "decode big.clusters -o out.tree"
run_case header/las-count fail big.las "head -c 107 $v/v.las > big.las; printf '\377\377\377\377' >> big.las; tail -c +112 $v/v.las | head -c 2000 >> big.las" \
  "encode big.las -o out.clusters"
run_case header/glb-length fail big.glb "head -c 8 $v/v.glb > big.glb; printf '\377\377\377\177' >> big.glb; tail -c +13 $v/v.glb >> big.glb" \
  "encode big.glb -o out.clusters"
run_case header/gltf-accessor fail huge.gltf \
  "printf '%s' '{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":2000000000,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":[1,1,1]}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0}' > huge.gltf" \
  "encode huge.gltf -o out.clusters"
run_case header/obj-index fail bad.obj "printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2000000000\n' > bad.obj" \
  "stages bad.obj --at 0.5 -o out.tree"
run_case header/obj-three-points fail t.obj "printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > t.obj" \
  "encode t.obj -o out.clusters"
png_header() {  # WIDTH HEIGHT: a PNG header declaring WIDTH x HEIGHT with one row of data
  python3 - "$1" "$2" <<'EOF'
import struct, sys, zlib
w, h = int(sys.argv[1]), int(sys.argv[2])
def chunk(t, d):
    return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
ihdr = struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)
sys.stdout.buffer.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) +
                        chunk(b"IDAT", zlib.compress(b"\0" + b"\0" * 3)) + chunk(b"IEND", b""))
EOF
}
for size in "20000 20000" "16384 16384" "8000 6000" "4000 3000" "100000 1" "1 100000"; do
  set -- $size
  run_case "header/png-$1x$2-crown" fail big.png "$(declare -f png_header); png_header $1 $2 > big.png" \
    "crown big.png -o out"
  run_case "header/png-$1x$2-mask" fail big.png "$(declare -f png_header); png_header $1 $2 > big.png" \
    "crown $v/v.png --mask big.png -o out"
  run_case "header/png-$1x$2-heightfield" fail "" \
    "$(declare -f png_header); png_header $1 $2 > h.png; printf '{\"fspm_scene\": 2, \"terrain\": {\"heightfield\": \"h.png\", \"metres_per_pixel\": 1}}' > t.json" \
    "mesh t.json -o out.glb"
done

# --- growth that outruns any memory ------------------------------------------------------------
run_case grow/doubling-modules fail "" \
  "printf 'derivation length: 60\nAxiom: A(1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20)\nA(a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,q,r,s,t) --> A(a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,q,r,s,t)A(a,b,c,d,e,f,g,h,i,j,k,l,m,n,o,p,q,r,s,t)\n' > w.l" \
  "lsystem derive w.l"
run_case grow/branching fail "" "printf 'derivation length: 60\nAxiom: A\nA --> F[+A][-A]\n' > b.l" \
  "lsystem interpret b.l -o out.tree"
run_case grow/compressed-billion-steps fail "" ":" \
  "lsystem derive $v/v.l --compressed --steps 1000000000"
run_case grow/compressed-unshared fail "" \
  "printf 'derivation length: 60\nAxiom: A(1)\nA(x) --> F(x)[+A(x+1)][-A(x*2)]\n' > p.l" "lsystem derive p.l --compressed"
run_case grow/compressed-40-json ok "" ":" "lsystem derive $v/v.l --compressed --steps 40 --json"
run_case grow/interpret-compressed-mesh fail "" ":" \
  "lsystem interpret $v/v.l --compressed --steps 40 -o out.glb"
run_case grow/branch-copies fail "" ":" \
  "stages $v/v.treeb --at 1 -o out.tree $(for _ in $(seq 30); do printf -- '--copy-branch 614:631 '; done)"
run_case grow/distance-star fail "" \
  "{ printf '('; for _ in \$(seq 5000); do printf '1,'; done; printf '1);\n'; } > s.nwk" "distance s.nwk s.nwk"
run_case grow/encode-many-points fail "" \
  "awk 'BEGIN { for (i = 0; i < 3000000; i++) print i % 317, i % 101, i % 53 }' > c.xyz" \
  "encode c.xyz -o out.clusters"
run_case grow/render-many-points fail "" \
  "awk 'BEGIN { for (i = 0; i < 3000000; i++) print i % 317, i % 101, i % 53 }' > c.xyz" \
  "render c.xyz -o out.png"
run_case grow/crown-cubemaps fail "" ":" "crown $v/v.png -o out --cubemap-size 2048"
run_case grow/sweep-axis fail "" \
  "cp $v/experiment.toml e.toml; printf '[sweep]\n\"x.a\" = { range = [0, 100000000] }\n' >> e.toml" \
  "run e.toml --out out"
run_case grow/replicates fail "" ":" "run $v/experiment.toml --replicates 2000000000 --out out"
run_case grow/years fail "" ":" "grow $v/growth.toml --years 100000 -o out.tree"
run_case grow/greenlab-cycles fail "" ":" "greenlab simulate $v/plant.toml --cycles 100000000 -o out.ctree"
run_case grow/stage-steps-over fail "" ":" "stages $v/v.treeb --steps 100001 -o out"
run_case grow/light-directions fail "" ":" \
  "light --scene $v/scene.json --points $v/points.csv --directions 1000000000"
run_case grow/scan-density fail "" ":" "scan $v/v.treeb -o out.xyz --density 100000000"
run_case grow/render-size fail "" ":" "render $v/v.nwk -o out.png --size 100000x100000"

# --- outputs that cannot be written ------------------------------------------------------------
full_case() {  # NAME OUT ARGS: OUT is a link to /dev/full
  run_case "full/$1" fail "$2" "ln -s /dev/full $2" "$3"
}
full_case tree-convert out.tree "tree convert $v/v.nwk out.tree"
full_case tree-convert-treeb out.treeb "tree convert $v/v.nwk out.treeb"
full_case simulate out.ctree "greenlab simulate $v/plant.toml -o out.ctree"
full_case reconstruct out.tree "greenlab reconstruct $v/v.ctree -o out.tree"
full_case grow out.tree "grow $v/growth.toml -o out.tree"
full_case interpret out.tree "lsystem interpret $v/v.l -o out.tree"
full_case derive-ctree out.ctree "lsystem derive $v/v.l -o out.ctree"
full_case stages out.tree "stages $v/v.treeb --at 0.5 -o out.tree"
full_case scan out.xyz "scan $v/v.treeb -o out.xyz"
full_case encode out.clusters "encode $v/v.treeb -o out.clusters"
full_case decode out.tree "decode $v/v.clusters -o out.tree"
full_case mesh-obj out.obj "mesh $v/v.treeb -o out.obj"
full_case mesh-glb out.glb "mesh $v/v.treeb -o out.glb"
full_case mesh-ply out.ply "mesh $v/v.treeb -o out.ply"
full_case mesh-vtp out.vtp "mesh $v/v.treeb -o out.vtp"
full_case render out.png "render $v/v.nwk -o out.png"
full_case light out.csv "light --scene $v/scene.json --points $v/points.csv -o out.csv"
full_case adapt out.tree "adapt $v/v.treeb --scene $v/scene.json -o out.tree"
full_case crown-mesh out.obj "crown $v/v.png -o out.obj"
full_case crown-preview p.png "crown $v/v.png -o out --preview p.png"
full_case export out.csv "results export $v/results --csv -o out.csv"
for cmd in "tree info $v/v.nwk --json" "lsystem derive $v/v.l --string" "light --scene $v/scene.json --points $v/points.csv" \
  "distance $v/v.nwk $v/v.nwk" "stats describe $v/a.csv" "results export $v/results --csv" "--help"; do
  run_case "full/stdout-${cmd%% *}" fail "standard output" ":" "$cmd >/dev/full"
done

# --- options given wrong ------------------------------------------------------------------------
for opt in "--steps -1" "--steps nan" "--steps 1e300" "--steps ''" "--seed -1" "--budget 0" \
  "--define X" "--define =1" "--variants 0" "--unknown-option" "-o" "--steps 3 --steps 4"; do
  run_case "option/interpret $opt" fail "" ":" "lsystem interpret $v/v.l -o out.tree $opt"
done
for opt in "--at -0.5" "--at 2" "--at nan" "--steps 0" "--at 0.5 --steps 3" "--age-branch 1:x" \
  "--copy-branch 1" "--copy-branch 99999:1" "--profile -1" "--season-years -3" "--format xyz"; do
  run_case "option/stages $opt" fail "" ":" "stages $v/v.treeb -o out.tree $opt"
done
for opt in "--height-m 0" "--height-m inf" "--depth-ratio nan" "--k 0" "--connectivity 6" \
  "--cubemap-size 7" "--relief 2" "--seed -4" "--height-m 5 --image-height-m 5" "-o out.xyz"; do
  run_case "option/crown $opt" fail "" ":" "crown $v/v.png -o out $opt"
done
for opt in "--size 0x0" "--size -1x10" "--size 1000000000x1" "--size 10" "--view nowhere" "--frame -1" "--format txt"; do
  run_case "option/render $opt" fail "" ":" "render $v/v.nwk -o out.png $opt"
done
for opt in "--directions 0" "--directions -1" "--directions 1e99" "--points" "--scene nowhere.json"; do
  run_case "option/light $opt" fail "" ":" "light --scene $v/scene.json --points $v/points.csv $opt"
done
for opt in "--years -1" "--years nan" "--seed 1e30" "--max-internodes 0" "--set nonsense=1" "--set years=abc" "--scene $v/v.png"; do
  run_case "option/grow $opt" fail "" ":" "grow $v/growth.toml -o out.tree $opt"
done
for opt in "--memory-limit 0" "--memory-limit -1G" "--memory-limit 1X" "--memory-limit ''" \
  "--memory-limit 1e30" "--length-unit furlong" "--mtg-scale -1" "--plant ''"; do
  run_case "option/global $opt" fail "" ":" "$opt tree info $v/v.nwk"
done
run_case option/same-file fail "" "cp $v/v.nwk t.nwk" "tree convert t.nwk t.nwk"
run_case option/same-output fail "" ":" "stages $v/v.treeb --at 0.5 --skeleton o.tree -o ./o.tree"
run_case option/missing-output-folder fail "" ":" "mesh $v/v.treeb -o nowhere/m.obj"
run_case option/encode-text-ext fail "" ":" "encode $v/v.treeb -o out.txt"
run_case option/no-command fail "" ":" ""
run_case option/unknown-command fail "" ":" "frobnicate"

# --- a key given twice, in every TOML and JSON input kind ---------------------------------------
# The last value would silently win: each is refused with the file named.
dup_toml() {  # NAME FILE ARGS: appends a second [TABLE] key to a copy of FILE
  run_case "duplicate/$1" fail "in.toml" "$2" "$3"
}
dup_toml plant-key "sed 's/^cycles = 12$/cycles = 12\\ncycles = 3/' $v/plant.toml > in.toml" \
  "greenlab simulate in.toml -o out.ctree"
dup_toml growth-key "sed 's/^years = 20$/years = 20\\nyears = 2/' $v/growth.toml > in.toml" "grow in.toml -o out.tree"
dup_toml plant-table "cp $v/plant.toml in.toml; grep -m 1 '^\[' $v/plant.toml >> in.toml" "greenlab simulate in.toml -o out.ctree"
dup_toml growth-key-at-end "cp $v/growth.toml in.toml; echo 'preset = \"B\"' >> in.toml" "grow in.toml -o out.tree"
dup_toml experiment-key "printf '[experiment]\nname = \"s\"\nname = \"t\"\n[model]\nkind = \"synthetic\"\n' > in.toml" "run in.toml --out out"
dup_toml experiment-table "printf '[experiment]\nname = \"s\"\n[model]\nkind = \"synthetic\"\n[model]\nkind = \"lsystem\"\n' > in.toml" "run in.toml --out out"
dup_toml experiment-sweep-key "printf '[experiment]\nname = \"s\"\n[model]\nkind = \"synthetic\"\n[sweep]\nnodes = [2]\nnodes = [3]\n' > in.toml" "run in.toml --out out"
dup_toml experiment-dotted "printf '[experiment]\nname = \"s\"\nexperiment.name = \"t\"\n[model]\nkind = \"synthetic\"\n' > in.toml" "run in.toml --out out"
run_case duplicate/scene-top fail in.json \
  "printf '{\"fspm_scene\": 2, \"fspm_scene\": 2, \"obstacles\": []}' > in.json" "mesh in.json -o out.glb"
run_case duplicate/scene-obstacle fail in.json \
  "printf '{\"fspm_scene\": 2, \"obstacles\": [{\"type\": \"box\", \"type\": \"sphere\", \"center\": [0,0,0], \"size\": [1,1,1]}]}' > in.json" \
  "light --scene in.json --points $v/points.csv"
run_case duplicate/scene-terrain fail in.json \
  "printf '{\"fspm_scene\": 2, \"terrain\": {\"heightfield\": \"a.png\", \"heightfield\": \"b.png\", \"metres_per_pixel\": 1}}' > in.json" \
  "mesh in.json -o out.glb"
run_case duplicate/scene-for-grow fail in.json \
  "printf '{\"fspm_scene\": 2, \"obstacles\": [], \"obstacles\": []}' > in.json" "grow $v/growth.toml --scene in.json -o out.tree"
run_case duplicate/gltf-asset any "" \
  "sed 's/\"asset\":{/\"asset\":{\"version\":\"1.0\",/' $v/v.gltf > in.gltf" "encode in.gltf -o out.clusters"
run_case duplicate/crown-cubemaps-json fail crown_cubemaps.json \
  "\"$FSPM\" -q crown $v/v.png -o c; sed -i 's/\"cubemap_size\": \\([0-9]*\\),/\"cubemap_size\": \\1, \"cubemap_size\": 8,/' c/crown_cubemaps.json" \
  "view c/crown.glb --ray-cast --frames 1 --size 64x64 --screenshot v.png"

# --- headers that lie about what follows: LAS, PCD, glTF -----------------------------------------
las_patch() {  # OFFSET BYTES (printf escapes): a copy of the valid LAS with BYTES at OFFSET
  echo "cp $v/v.las in.las; printf '$2' | dd of=in.las bs=1 seek=$1 conv=notrunc 2>/dev/null"
}
run_case header/las-offset-past-end fail in.las "$(las_patch 96 '\377\377\377\177')" "encode in.las -o out.clusters"
run_case header/las-offset-in-header fail in.las "$(las_patch 96 '\010\000\000\000')" "encode in.las -o out.clusters"
run_case header/las-record-length-0 fail in.las "$(las_patch 105 '\000\000')" "encode in.las -o out.clusters"
run_case header/las-record-length-1 fail in.las "$(las_patch 105 '\001\000')" "encode in.las -o out.clusters"
run_case header/las-format-99 fail in.las "$(las_patch 104 '\143')" "encode in.las -o out.clusters"
run_case header/las-scale-zero any "" "$(las_patch 131 '\000\000\000\000\000\000\000\000')" "encode in.las -o out.clusters"
run_case header/las-scale-nan fail in.las "$(las_patch 131 '\000\000\000\000\000\000\370\177')" "encode in.las -o out.clusters"
run_case header/las-header-size-huge fail in.las "$(las_patch 94 '\377\377')" "encode in.las -o out.clusters"
run_case header/las-vlr-count-huge any in.las "$(las_patch 100 '\377\377\377\377')" "encode in.las -o out.clusters"
run_case header/las-count-zero fail in.las "$(las_patch 107 '\000\000\000\000')" "encode in.las -o out.clusters"
run_case header/las-truncated-header fail in.las "head -c 200 $v/v.las > in.las" "encode in.las -o out.clusters"
run_case header/las-version-9 fail in.las "$(las_patch 24 '\011\011')" "encode in.las -o out.clusters"
pcd() {  # FIELDS SIZE TYPE COUNT WIDTH HEIGHT POINTS DATA: a PCD header
  printf 'VERSION .7\nFIELDS %s\nSIZE %s\nTYPE %s\nCOUNT %s\nWIDTH %s\nHEIGHT %s\nPOINTS %s\nDATA %s\n' "$@"
}
pcd_case() {  # NAME SETUP-TAIL HEADER-ARGS...
  local name=$1 tail=$2
  shift 2
  run_case "header/pcd-$name" fail in.pcd "$(declare -f pcd); pcd $(printf "'%s' " "$@") > in.pcd; $tail" \
    "encode in.pcd -o out.clusters"
}
pcd_case points-not-width "printf '0 0 0\n1 1 1\n' >> in.pcd" "x y z" "4 4 4" "F F F" "1 1 1" 2 1 5 ascii
pcd_case width-times-height "head -c 24 /dev/zero >> in.pcd" "x y z" "4 4 4" "F F F" "1 1 1" 65536 65536 2 binary
pcd_case size-zero "head -c 24 /dev/zero >> in.pcd" "x y z" "0 0 0" "F F F" "1 1 1" 2 1 2 binary
pcd_case size-mismatch "head -c 24 /dev/zero >> in.pcd" "x y z" "4 4" "F F F" "1 1 1" 2 1 2 binary
pcd_case no-x "printf '0 0\n' >> in.pcd" "a b" "4 4" "F F" "1 1" 1 1 1 ascii
pcd_case count-huge "head -c 24 /dev/zero >> in.pcd" "x y z" "4 4 4" "F F F" "1 1 1000000000" 2 1 2 binary
pcd_case type-unknown "head -c 24 /dev/zero >> in.pcd" "x y z" "4 4 4" "Q Q Q" "1 1 1" 2 1 2 binary
pcd_case size-3 "head -c 24 /dev/zero >> in.pcd" "x y z" "3 3 3" "F F F" "1 1 1" 2 1 2 binary
pcd_case compressed-lying "printf '\377\377\377\177\377\377\377\177' >> in.pcd; head -c 16 /dev/zero >> in.pcd" "x y z" "4 4 4" "F F F" "1 1 1" 2 1 2 binary_compressed
pcd_case negative-points "printf '0 0 0\n' >> in.pcd" "x y z" "4 4 4" "F F F" "1 1 1" -1 1 -1 ascii
gltf_case() {  # NAME JSON (the glTF text; expected refused)
  run_case "header/gltf-$1" fail in.gltf "printf '%s' '$2' > in.gltf" "encode in.gltf -o out.clusters"
}
b64='AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA'
gl_head='{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,'$b64'"}]'
gl_tail=',"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}'
gltf_case view-past-buffer "$gl_head"',"bufferViews":[{"buffer":0,"byteLength":36000000}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}]'"$gl_tail"
gltf_case view-offset-past-buffer "$gl_head"',"bufferViews":[{"buffer":0,"byteOffset":4000000000,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}]'"$gl_tail"
gltf_case accessor-offset "$gl_head"',"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"byteOffset":30,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}]'"$gl_tail"
gltf_case stride-huge "$gl_head"',"bufferViews":[{"buffer":0,"byteLength":36,"byteStride":252}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}]'"$gl_tail"
gltf_case missing-buffer-file '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"nowhere.bin"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}]'"$gl_tail"
gltf_case buffer-uri-escapes '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"../../../../../../etc/hostname"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}]'"$gl_tail"
gltf_case buffer-length-lies '{"asset":{"version":"2.0"},"buffers":[{"byteLength":4000000000,"uri":"data:application/octet-stream;base64,'$b64'"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}]'"$gl_tail"
gltf_case index-out-of-range "$gl_head"',"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteLength":12}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},{"bufferView":1,"componentType":5125,"count":3,"type":"SCALAR"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}'
gltf_case accessor-missing "$gl_head"',"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[]'"$gl_tail"
gltf_case node-cycle "$gl_head"',"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0,"children":[1]},{"children":[0]}],"scenes":[{"nodes":[0]}],"scene":0}'
run_case header/glb-chunk-length fail in.glb "head -c 12 $v/v.glb > in.glb; printf '\377\377\377\177' >> in.glb; tail -c +17 $v/v.glb >> in.glb" \
  "encode in.glb -o out.clusters"
run_case header/glb-version-9 fail in.glb "head -c 4 $v/v.glb > in.glb; printf '\011\000\000\000' >> in.glb; tail -c +9 $v/v.glb >> in.glb" \
  "encode in.glb -o out.clusters"
run_case header/ply-stray-bytes fail in.ply "$(declare -f ply_header); { ply_header 2 binary_little_endian; head -c 28 /dev/zero; } > in.ply" \
  "encode in.ply -o out.clusters"
run_case header/ply-fewer-lines fail in.ply "$(declare -f ply_header); { ply_header 5 ascii; echo 0 0 0; echo 1 1 1; } > in.ply" \
  "encode in.ply -o out.clusters"

# --- FIFOs given where a secondary input goes --------------------------------------------------
fifo_case() {  # NAME VALID FILE ARGS [SETUP]: FILE is a FIFO fed with VALID
  run_case "fifo/$1" any "" "${5:-:}; mkfifo $3; (timeout 20 sh -c 'cat $2 > $3' &)" "$4"
}
fifo_case light-points "$v/points.csv" p.csv "light --scene $v/scene.json --points p.csv"
fifo_case light-scene "$v/scene.json" s.json "light --scene s.json --points $v/points.csv"
fifo_case grow-scene "$v/scene.json" s.json "grow $v/growth.toml --scene s.json -o out.tree"
fifo_case adapt-scene "$v/scene.json" s.json "adapt $v/v.treeb --scene s.json -o out.tree"
fifo_case crown-mask "$v/v.png" m.png "crown $v/v.png --mask m.png -o out"
fifo_case view-file "$v/m.v" f.v "lsystem interpret $v/m.l --view f.v -o out.tree"
fifo_case distance-second "$v/v.nwk" b.nwk "distance $v/v.nwk b.nwk"
fifo_case ttest-second "$v/a.csv" b.csv "stats ttest $v/a.csv b.csv"
fifo_case heightfield "$v/v.png" h.png "mesh t.json -o out.glb" \
  "printf '{\"fspm_scene\": 2, \"terrain\": {\"heightfield\": \"h.png\", \"metres_per_pixel\": 1}}' > t.json"
fifo_case experiment-model "$v/v.l" m.l "run e.toml --out out" \
  "printf '[experiment]\\nname = \"m\"\\n[model]\\nkind = \"lsystem\"\\nfile = \"m.l\"\\n' > e.toml"
fifo_case scene-info "$v/scene.json" s.json "scene info s.json"
fifo_case mesh-obj "$v/v.obj" m.obj "mesh m.obj -o out.glb"
fifo_case render-ply "$v/v.ply" p.ply "render p.ply -o out.png"
fifo_case decode-clusters "$v/v.clusters" c.clusters "decode c.clusters -o out.tree"
fifo_case mtg-convert "$v/v.mtg" t.mtg "tree convert t.mtg out.tree"

# --- more outputs on a full disk ---------------------------------------------------------------
full_case tree-convert-mtg out.mtg "tree convert $v/v.nwk out.mtg"
full_case tree-convert-nwk out.nwk "tree convert $v/v.treeb out.nwk"
full_case interpret-glb out.glb "lsystem interpret $v/v.l -o out.glb"
full_case interpret-obj out.obj "lsystem interpret $v/v.l -o out.obj"
full_case scan-ply out.ply "scan $v/v.treeb -o out.ply"
full_case stages-skeleton sk.tree "stages $v/v.obj --at 0.5 -o out.tree --skeleton sk.tree"
full_case reconstruct-glb out.glb "greenlab reconstruct $v/v.ctree -o out.glb"
full_case decode-glb out.glb "decode $v/v.clusters -o out.glb"
full_case mesh-skin out.glb "mesh $v/v.treeb -o out.glb --skin"
full_case render-jpg out.jpg "render $v/v.nwk -o out.jpg"
full_case export-json out.json "results export $v/results --json -o out.json"
run_case full/crown-folder-glb fail crown.glb "mkdir out; ln -s /dev/full out/crown.glb" "crown $v/v.png -o out"
run_case full/report-md fail "report.md" "cp -r $v/results r; ln -s /dev/full r/report.md" "report r --no-figures"
run_case full/compare-pairs fail "pairs.csv" "cp -r $v/cmp r; rm -f r/pairs.csv; ln -s /dev/full r/pairs.csv" "compare r"
run_case full/stages-steps fail "" "mkdir out; ln -s /dev/full out/stage_001.treeb" "stages $v/v.treeb --steps 3 -o out"
for cmd in "tree info $v/v.mtg --json" "stats ttest $v/a.csv $v/a.csv" "results show $v/results" \
  "results export $v/results --json" "lsystem derive $v/v.l --compressed --steps 40 --json" \
  "light --scene $v/scene.json --points $v/points.csv --json" "distance $v/v.nwk $v/v.treeb --json"; do
  run_case "full/stdout-${cmd%% *}-${cmd##* }" fail "standard output" ":" "$cmd >/dev/full"
done

# --- numeric options at the edges of what a double or a 64-bit count holds ---------------------
# A value in range may still ask for the impossible (1e-320 m between rings): it must end within
# the time limit and the memory budget, or be refused.
absurd() {  # BASE OPTION...: each OPTION with each absurd value
  local base=$1
  shift
  local opt val
  for opt in "$@"; do
    for val in 1e308 1e-320 9223372036854775808; do
      run_case "absurd/${base%% *} $opt $val" any "" "cp -r $v/cmp r 2>/dev/null" "$base $opt $val"
    done
  done
}
absurd "light --scene $v/scene.json --points $v/points.csv" --directions --global-radiation --transmittance
absurd "light --scene $v/scene.json --points $v/points.csv --global-radiation 500" --latitude --utc-offset
absurd "grow $v/growth.toml -o out.tree" --years --max-internodes --seed
absurd "lsystem derive $v/v.l" --steps --budget
absurd "lsystem derive $v/v.l --compressed" --variants
absurd "lsystem interpret $v/v.l -o out.tree" --detail
absurd "greenlab simulate $v/plant.toml -o out.ctree" --cycles
absurd "greenlab reconstruct $v/v.ctree -o out.tree" --age --max-order
absurd "distance $v/v.nwk $v/v.treeb" --main-skeleton
absurd "stats describe $v/a.csv" --level
absurd "adapt $v/v.treeb --scene $v/scene.json -o out.tree" --skeleton-radius --pruning-strength --phototropism
absurd "stages $v/v.treeb --at 0.5 -o out.tree" --season-years --added-gamma --profile
absurd "stages $v/v.treeb -o out" --steps
absurd "stages $v/v.obj --at 0.5 -o out.tree" --join-distance
absurd "encode $v/v.xyz -o out.clusters" --beta --fs --root-diameter --bin-length --neighbours
absurd "scan $v/v.treeb -o out.xyz" --scanners --density --noise-mm
absurd "run $v/experiment.toml --out out" --jobs --time-limit --replicates --shards
absurd "compare r" --jobs
absurd "mesh $v/v.treeb -o out.obj" --edge-length --max-sides
absurd "mesh $v/v.treeb -o out.glb --skin" --animate --fps
absurd "render $v/v.nwk -o out.png" --ortho-height --wind-time --lod-distance
absurd "decode $v/v.clusters -o out.tree" --branchlets --lod --prune-distance
absurd "crown $v/v.png -o out" --height-m --depth-ratio --k --trunk-radius-m

# --- jobs sharing the memory limit, stages kept for the viewer, MTG code too large --------------
run_case limits/run-jobs-share ok "" \
  "printf 'derivation length: 19\nAxiom: A\nA --> F[+A][-A]\n' > t.l; printf '[experiment]\nname = \"m\"\nreplicates = 4\n[model]\nkind = \"lsystem\"\nfile = \"t.l\"\n' > e.toml" \
  "run e.toml --out out --jobs 4"
run_case limits/run-jobs-each-over any "" \
  "printf 'derivation length: 24\nAxiom: A\nA --> F[+A][-A]\n' > t.l; printf '[experiment]\nname = \"m\"\nreplicates = 2\n[model]\nkind = \"lsystem\"\nfile = \"t.l\"\n' > e.toml" \
  "run e.toml --out out --jobs 2"
run_case limits/compare-jobs ok "" "cp -r $v/cmp r" "compare r --jobs 8"
run_case limits/view-stages fail "" ":" "view $v/v.treeb --stages 2000 --frames 1 --screenshot v.png"
run_case limits/view-ages fail "" ":" "view $v/v.ctree --ages $(seq -s, 1 400) --frames 1 --screenshot v.png"
run_case limits/mtg-deep-convert fail out.mtg "printf 'MTG:\nENTITY-CODE\n/I2+.+nnnnnnnPn210011\n' > d.mtg" "tree convert d.mtg out.mtg"
run_case limits/mtg-deep-interpret fail out.mtg "printf 'derivation length: 17000\nAxiom: A\nA --> F[+A]\n' > d.l" "lsystem interpret d.l -o out.mtg"
run_case limits/derive-saturated-json ok "" ":" "lsystem derive $v/v.l --compressed --steps 28 --json"

# --- counts in plant files, numbers strtod reads as nan, inputs that draw nothing ---------------
plant_head='[plant]\ncycles = 5\n[[age]]\nindex = 1\nduration = 5\nnext_age = 0\n'
run_case plant/unit-count fail "" "printf '${plant_head}units = [ { count = 1000000000 } ]\n' > p.toml" \
  "greenlab simulate p.toml -o out.ctree"
run_case plant/bud-count fail "" \
  "printf '${plant_head}branching_delay = 1\nunits = [ { count = 1, axillary = [ { age = 1, count = 1000000000 } ] } ]\n' > p.toml" \
  "greenlab simulate p.toml -o out.ctree"
run_case plant/expansion fail p.toml "printf '${plant_head}units = [ { count = 1 } ]\nleaf_expansion = 100000000\n' > p.toml" \
  "greenlab simulate p.toml -o out.ctree"
for val in nan inf 1e309; do
  run_case "view/angle-$val" fail in.v "printf 'angle increment: $val\n' > in.v" "lsystem interpret $v/v.l --view in.v -o out.glb"
  run_case "mtg/length-$val" any "" "sed 's|^/P1/U1/E1\t\t\t10|/P1/U1/E1\t\t\t$val|' $v/v.mtg > in.mtg" "tree convert in.mtg out.tree"
done
run_case mtg/length-nan-info fail in.mtg "sed 's|^/P1/U1/E1\t\t\t10|/P1/U1/E1\t\t\tnan|' $v/v.mtg > in.mtg" "tree info in.mtg"
run_case mtg/diameter-negative fail in.mtg "sed 's|^/P1/U1/E1\t\t\t10\t2|/P1/U1/E1\t\t\t10\t-2|' $v/v.mtg > in.mtg" "tree convert in.mtg out.tree"
run_case draws-nothing/mesh-nwk fail out.glb ":" "mesh $v/v.nwk -o out.glb"
run_case draws-nothing/interpret-f0 fail out.obj "printf 'Axiom: F(0)\n' > z.l" "lsystem interpret z.l -o out.obj"
run_case draws-nothing/interpret-inf fail "" "printf 'Axiom: F(1e308*1e308)\n' > z.l" "lsystem interpret z.l -o out.glb"
run_case draws-nothing/interpret-nan-width fail "" "printf 'Axiom: !(sqrt(-1))F(1)\n' > z.l" "lsystem interpret z.l -o out.ply"
run_case draws-nothing/scan fail out.xyz "printf 'Axiom: F(0)\n' > z.l; \"$FSPM\" -q lsystem interpret z.l -o z.tree" "scan z.tree -o out.xyz"
run_case names/newline fail 'no\nsuch' ":" "tree info \$'no\\nsuch.nwk'"
run_case names/escape fail 'e\x1b' "printf '((' > \$'e\\033[2Jsc.nwk'" "tree info \$'e\\033[2Jsc.nwk'"

# --- signals: stopped cleanly, nothing half written -------------------------------------------
run_signal signal/grow-term TERM 143 out.tree "grow $v/growth.toml --years 60 -o out.tree"
run_signal signal/grow-int INT 130 out.tree "grow $v/growth.toml --years 60 -o out.tree"
run_signal signal/scan-term TERM 143 out.xyz "scan $v/v.treeb --density 100000 -o out.xyz"
run_signal signal/scan-int INT 130 out.xyz "scan $v/v.treeb --density 100000 -o out.xyz"
run_signal signal/stages-term TERM 143 "" "stages $v/v.treeb --steps 100000 -o out"
run_signal signal/render-term TERM 143 out.png "render $v/v.treeb -o out.png --size 4000x4000"
run_signal signal/crown-term TERM 143 out "crown $v/v.png -o out --cubemap-size 1024"
run_signal signal/crown-int INT 130 out "crown $v/v.png -o out --cubemap-size 1024"
run_signal signal/encode-term TERM 143 out.clusters "encode $v/v.las -o out.clusters"
run_signal signal/run-term TERM 143 "" "run $ex/experiments/branching.toml --out out"
run_signal signal/run-int INT 130 "" "run $ex/experiments/branching.toml --out out"

elapsed=$(($(date +%s) - started))
echo "hostile_audit: $cases cases in ${elapsed} s, $findings finding(s); largest peak resident" \
  "memory $((max_rss_kib / 1024)) MiB under --memory-limit ${LIMIT_MIB}M"
[ "$findings" -eq 0 ]
