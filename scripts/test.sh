#!/usr/bin/env bash
# Installs the dependencies, builds everything (Release) in build/ and runs the whole test suite.
# Exits non-zero if the build or any test fails.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j2
