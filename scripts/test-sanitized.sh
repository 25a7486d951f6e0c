#!/usr/bin/env bash
# The test suite again under AddressSanitizer + UndefinedBehaviorSanitizer
# (build-asan/), then each libFuzzer target for a short, seeded run
# (build-fuzz/, clang). Any sanitizer report fails.
set -euo pipefail
cd "$(dirname "$0")/.."
t0=$(date +%s)
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DREPOSE_SANITIZE=ON \
  -DREPOSE_BUILD_BENCHMARKS=OFF >build-asan.configure.log 2>&1 || { cat build-asan.configure.log; exit 1; }
cmake --build build-asan -j"$(nproc)"
t1=$(date +%s)
echo "sanitized: build took $(( t1 - t0 )) s"
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# the randomized ground-model invariants run fewer seeds under the sanitizers (~5x slower)
export REPOSE_RANDOM_CASES="${REPOSE_RANDOM_CASES:-40}"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E "${REPOSE_ASAN_EXCLUDE:-^$}"
t2=$(date +%s)
echo "sanitized: suite took $(( t2 - t1 )) s"
if [ -f tests/fuzz/CMakeLists.txt ]; then
  bash scripts/fuzz.sh "${REPOSE_FUZZ_SECONDS:-10}"
  echo "sanitized: fuzz build and runs took $(( $(date +%s) - t2 )) s"
fi
