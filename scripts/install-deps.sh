#!/usr/bin/env bash
# Installs the Debian 12 packages Hausdorff Lens needs to build, test and run (see README.md,
# "Dependencies"). Idempotent: when every package is already installed it does nothing, quickly.
# Run as root (or as a user with sudo). Extra package names given as arguments are installed too
# (scripts/fuzz.sh adds clang and libFuzzer's runtime this way).
set -euo pipefail

PACKAGES=(
  build-essential cmake g++
  libopenmesh-dev libtinygltf-dev
  libglfw3-dev libimgui-dev libglm-dev libstb-dev
  libgtest-dev googletest libbenchmark-dev
  xvfb xauth mesa-utils libgl1-mesa-dri
  python3-dev pybind11-dev python3-numpy python3-pytest
  "$@"
)

missing=()
for p in "${PACKAGES[@]}"; do
  if [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" != "install ok installed" ]; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages are installed"
  exit 0
fi

SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  else
    echo "install-deps: missing packages: ${missing[*]}; run this script as root" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${PACKAGES[@]}"
