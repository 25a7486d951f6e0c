#!/usr/bin/env bash
# The README's first command: install what is missing, build, run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash scripts/install-deps.sh
bash scripts/build.sh repose   # the program only; scripts/test.sh builds the tests
echo "setup: built in $(( $(date +%s) - start )) s; running the default experiment"
bash scripts/main-job.sh
echo "setup: done in $(( $(date +%s) - start )) s"
