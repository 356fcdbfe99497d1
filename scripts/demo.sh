#!/usr/bin/env bash
# Installs the dependencies, builds (Release) in build/ and measures the demo pair in assets/
# (made by scripts/make_demo.py). The interactive debugger `hlens` does not exist yet.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target hlens-cli
build/bin/hlens-cli distance assets/demo_a.obj assets/demo_b.obj
