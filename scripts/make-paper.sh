#!/usr/bin/env bash
# The paper, rebuilt from the experiments by one command (paper/README.md):
#   scripts/make-paper.sh [--quick|--full] [--out DIR] [--allow-mixed] [--status] [--skip ID]...
# Builds the `repose` program if needed (niced), then paper/tools/make_paper.py:
# says what is fresh, stale (and why) or missing, reruns what the mode allows,
# writes the generated macros, tables and figures and builds DIR/paper.pdf
# (default paper/out/paper.pdf). --quick (the default): short runs and the
# committed data/ only; --full: every experiment, the DEM ones included.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${REPOSE_PAPER_NO_BUILD:-0}" != 1 ]; then
  if [ -f build/CMakeCache.txt ]; then
    nice cmake --build build -j"$(nproc)" --target repose >/dev/null
  else
    nice bash scripts/build.sh repose >/dev/null
  fi
fi
exec /usr/bin/python3 paper/tools/make_paper.py "$@"
