#!/usr/bin/env bash
# What the real-browser tier needs: Debian's Chromium (a test tool's own browser
# download does not work here) and the Python packages playwright and voila.
# Usage: bash tests/browser/setup.sh   (PYTHON=path/to/python to choose the venv)
set -euo pipefail
cd "$(dirname "$0")/../.."
PY="${PYTHON:-.venv/bin/python}"
CHROMIUM="${DHLAB_CHROMIUM:-/usr/bin/chromium}"

if [ ! -x "$CHROMIUM" ]; then
  if [ "$(id -u)" = 0 ]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
  else
    echo "The browser tests need Chromium: sudo apt-get install -y chromium" >&2
    exit 1
  fi
fi
CONSTRAINTS=()
[ -f constraints.txt ] && CONSTRAINTS=(-c constraints.txt)
"$PY" -c "import playwright, voila" 2>/dev/null \
  || "$PY" -m pip install --quiet "${CONSTRAINTS[@]}" playwright voila
"$CHROMIUM" --version
