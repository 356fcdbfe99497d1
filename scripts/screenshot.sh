#!/usr/bin/env bash
# Regenerates docs/screenshot.png, the README's picture of the debugger on a real mesh pair:
# spot.obj (Keenan Crane, public domain; ../shared/meshes) against its 10% simplification, measured
# B against A (the coarse copy's triangles are the targets, so a target has many domains), target 50
# finished, with the domain view and its overlay, the graph of d^2, the event log and the timeline
# open, and the 3D view zoomed out to show the colour map.
#
#   bash scripts/screenshot.sh [OUT.png]      (default docs/screenshot.png)
#
# Installs the dependencies and builds hlens and hlens_make_pairs (Release, in build/) as
# scripts/demo.sh does, makes the simplified copy with hlens_make_pairs (OpenMesh quadric decimation,
# as bench/compare.sh makes its pairs) in a temporary directory, renders headless under xvfb-run and
# shrinks the PNG to 256 colours (scripts/shrink_png.py, standard library only). Exits non-zero on
# any failure, and when the debugger's state line does not show the expected target.
set -euo pipefail
cd "$(dirname "$0")/.."

OUT="${1:-docs/screenshot.png}"
SPOT="../shared/meshes/spot.obj"
TARGET=50
die() { echo "screenshot.sh: $*" >&2; exit 1; }
[ -f "$SPOT" ] || die "$SPOT not found (the shared meshes are expected next to the repository)"
command -v xvfb-run >/dev/null || die "xvfb-run not found (package xvfb; scripts/install-deps.sh installs it)"

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target hlens hlens_make_pairs || die "the build failed (see above)"
[ -x build/bin/hlens ] || die "build/bin/hlens was not built (GLFW, OpenGL or Dear ImGui missing?)"

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
build/bin/hlens_make_pairs simplify "$SPOT" "$tmp/spot_10.obj" 0.10 >/dev/null 2>&1 \
  || die "hlens_make_pairs failed on $SPOT"

# 1280x800 window; the wheel (6 steps out over the 3D view) shows the whole head around the target.
xvfb-run -a -s "-screen 0 1600x1000x24" build/bin/hlens "$SPOT" "$tmp/spot_10.obj" \
  --direction ba --target "$TARGET" --step end --overlay --graph --event-log \
  --size 1280x800 --wheel 1060,250,-6 --screenshot "$tmp/full.png" >"$tmp/state.json" \
  || die "hlens --screenshot failed"
grep -q "\"target\": $TARGET," "$tmp/state.json" || die "unexpected state line: $(head -c 300 "$tmp/state.json")"

mkdir -p "$(dirname "$OUT")"
python3 scripts/shrink_png.py "$tmp/full.png" "$tmp/small.png" || die "shrinking the PNG failed"
mv "$tmp/small.png" "$OUT"
echo "screenshot.sh: wrote $OUT ($(stat -c %s "$OUT") bytes)"
