#!/usr/bin/env bash
# Makes `import hlens` work in a virtual environment, offline: creates VENV (if needed) with
# Debian's /usr/bin/python3 and its system packages (numpy), and adds a .pth file pointing at the
# module built in build/python/ (so a rebuild is seen at once; nothing is copied or downloaded).
#   bash scripts/python-venv.sh VENV [BUILD_DIR]
set -euo pipefail
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: bash scripts/python-venv.sh VENV [BUILD_DIR]" >&2
  exit 2
fi
venv=$1
build=$(cd "${2:-$(dirname "$0")/../build}" && pwd)
if ! ls "$build"/python/hlens*.so >/dev/null 2>&1; then
  echo "python-venv: no module in $build/python: build first (cmake --build build --target hlens_python)" >&2
  exit 1
fi
python=/usr/bin/python3
[ -x "$python" ] || python=python3
[ -x "$venv/bin/python" ] || "$python" -m venv --system-site-packages --without-pip "$venv"
site=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
echo "$build/python" > "$site/hlens.pth"
echo "python-venv: $venv/bin/python can import hlens (from $build/python)"
