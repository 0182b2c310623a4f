#!/usr/bin/env bash
# Checks the formatting (.clang-format), builds, then runs every test: units, CLI end-to-end, fuzz corpus replay (build/); the same again
# under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/); then a bounded fuzz run of
# each target (TAPE_FUZZ_SECONDS, default 30 s each); the USB adapter core cross-compiled for a Cortex-M0+. Every stage runs even when one before it
# failed; the exit status is 1 when any failed.
set -uo pipefail
cd "$(dirname "$0")/.."
failed=()
stage() {
  local name=$1
  shift
  echo "test: $name"
  "$@" || { failed+=("$name"); return 1; }
}

werror=OFF
[ "${CI:-}" = "true" ] && werror=ON

stage format bash scripts/check-format.sh
stage build bash scripts/build.sh &&
  stage tests ctest --test-dir build --output-on-failure -j2

# The USB adapter's core for its microcontroller (Cortex-M0+): it must build, and its size is shown.
firmware() {
  local status=0
  bash scripts/firmware-build.sh || status=$?
  [ "$status" -eq 77 ] && return 0  # no cross compiler: the script said so
  return "$status"
}
stage firmware firmware

# -O1 -g1: half the compile time of -O2 -g, and still the file and line of every report. Any finding
# aborts the process, so the test fails; LeakSanitizer is on (ASan's default on Linux).
export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
stage sanitize-build cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
  -DTAPE_SANITIZE=ON -DTAPE_BUILD_BENCH=OFF -DTAPE_WERROR="$werror" >/dev/null &&
  stage sanitize-build cmake --build build-asan -j2 &&
  stage sanitize-tests ctest --test-dir build-asan --output-on-failure -j2 -L 'unit|cli|fuzz-corpus'
unset ASAN_OPTIONS UBSAN_OPTIONS

stage fuzz bash scripts/fuzz.sh "${TAPE_FUZZ_SECONDS:-30}"

if [ ${#failed[@]} -gt 0 ]; then
  echo "test: failed: ${failed[*]}" >&2
  exit 1
fi
echo "test: all passed"
