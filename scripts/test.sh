#!/usr/bin/env bash
# Installs the dependencies, builds everything (Release) in build/ and runs the whole test suite,
# including the debugger's tests (suite Gui), which run hlens headless on an Xvfb server.
# With CI set (.ci/run) it then runs scripts/sanitize.sh and scripts/fuzz.sh 60.
# Exits non-zero if the build or any test fails.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
# In CI the debugger must be built and its tests must not be skipped for want of Xvfb.
if [ -n "${CI:-}" ]; then
  if [ ! -x build/bin/hlens ]; then
    echo "test.sh: build/bin/hlens was not built (GLFW, OpenGL or Dear ImGui not found?)" >&2
    exit 1
  fi
  if ! command -v Xvfb >/dev/null 2>&1; then
    echo "test.sh: Xvfb is missing: the Gui tests would be skipped" >&2
    exit 1
  fi
fi
# The Gui tests' scratch directories (hlens_gui_*) must all be gone afterwards (issue 8): note
# those already there, and fail if the run leaves one more.
scratch_left() { ls -d "${TMPDIR:-/tmp}"/hlens_gui_* 2>/dev/null | sort || true; }
scratch_before="$(scratch_left)"
ctest --test-dir build --output-on-failure -j2
# In CI also: the whole suite again under ASan+UBSan (Debug, build-asan/), and every mesh reader
# fuzzed for 60 s (build-fuzz/). See README.md, "Sanitizers and fuzzing".
if [ -n "${CI:-}" ]; then
  bash scripts/sanitize.sh
  bash scripts/fuzz.sh 60
fi
left="$(comm -13 <(echo "$scratch_before") <(scratch_left) | sed '/^$/d')"
if [ -n "$left" ]; then
  echo "test.sh: the tests left scratch directories behind:" >&2
  echo "$left" >&2
  exit 1
fi
