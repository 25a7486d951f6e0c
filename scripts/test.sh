#!/usr/bin/env bash
# The README's second command: the whole test suite. Installs what is missing,
# builds, and runs ctest on the normal build; then the sanitized build and
# the short fuzz runs (scripts/test-sanitized.sh) unless REPOSE_QUICK=1.
set -euo pipefail
cd "$(dirname "$0")/.."
t0=$(date +%s)
bash scripts/install-deps.sh
bash scripts/build.sh
t1=$(date +%s)
echo "test: normal build took $(( t1 - t0 )) s"
ctest --test-dir build --output-on-failure -j"$(nproc)"
t2=$(date +%s)
echo "test: normal suite took $(( t2 - t1 )) s"
if [ "${REPOSE_QUICK:-0}" != 1 ] && [ -f scripts/test-sanitized.sh ]; then
  bash scripts/test-sanitized.sh
fi
echo "test: total $(( $(date +%s) - t0 )) s"
