#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (build-fuzz/) and runs each for
# SECONDS (default 10) with a fixed seed, after replaying its regression
# inputs. Longer by hand: scripts/fuzz.sh 600. A crash fails the script and
# leaves the input in build-fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DREPOSE_BUILD_FUZZERS=ON \
  -DREPOSE_BUILD_TESTS=OFF -DREPOSE_BUILD_BENCHMARKS=OFF >build-fuzz.configure.log 2>&1 \
  || { cat build-fuzz.configure.log; exit 1; }
cmake --build build-fuzz -j"$(nproc)" --target fuzzers
mkdir -p build-fuzz/artifacts
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
shopt -s nullglob
for bin in build-fuzz/fuzz/*_fuzzer; do
  name=$(basename "$bin" _fuzzer)
  regress=tests/fuzz/regressions/$name
  if [ -d "$regress" ] && [ -n "$(ls -A "$regress")" ]; then
    "$bin" -runs=0 "$regress"/* >/dev/null 2>&1 || { echo "fuzz: $name regression input fails"; "$bin" -runs=0 "$regress"/*; exit 1; }
  fi
  work=build-fuzz/corpus/$name
  mkdir -p "$work"
  log=build-fuzz/$name.log
  # -timeout: an input taking longer than 10 s is a hang; -rss_limit_mb (and the
  # malloc limit that follows it): an input that needs more than 2 GB is a finding
  "$bin" -seed=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix=build-fuzz/artifacts/"$name"- "$work" "tests/fuzz/corpus/$name" >"$log" 2>&1 \
    || { tail -40 "$log"; echo "fuzz: $name found a crash (input in build-fuzz/artifacts/)"; exit 1; }
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  echo "fuzz: $name ok: $runs runs in ${seconds} s, $rate exec/s, corpus $(ls "$work" | wc -l) inputs"
done
