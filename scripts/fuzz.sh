#!/usr/bin/env bash
# Builds the libFuzzer targets with clang-14 and runs each for a bounded time (default 30 s), one
# after the other, with its dictionary (tests/fuzz/NAME.dict) when it has one.
# New inputs go to a scratch folder; the committed corpus in tests/fuzz/corpus/ is only read.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
bash scripts/install-deps.sh test
# The one list of targets, shared with CMake.
targets=$(sed -n 's/^set(TAPE_FUZZ_TARGETS \(.*\))$/\1/p' tests/fuzz/targets.cmake)
[ -n "$targets" ] || { echo "fuzz: no targets in tests/fuzz/targets.cmake" >&2; exit 1; }
CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTAPE_BUILD_FUZZ=ON -DTAPE_BUILD_TESTS=OFF -DTAPE_BUILD_BENCH=OFF >/dev/null
# shellcheck disable=SC2046 # one word per target
cmake --build build-fuzz -j2 --target $(printf '%s_fuzz ' $targets)
for target in $targets; do
  scratch=$(mktemp -d)
  # One input taking over a minute is a hang: said then, not after libFuzzer's default 20 minutes.
  options=(-max_total_time="$seconds" -max_len=4096 -timeout=60 -print_final_stats=1)
  [ -f "tests/fuzz/$target.dict" ] && options+=(-dict="tests/fuzz/$target.dict")
  echo "fuzz: ${target}_fuzz for ${seconds} s"
  status=0
  build-fuzz/bin/${target}_fuzz "${options[@]}" "$scratch" "tests/fuzz/corpus/$target" >"$scratch.log" 2>&1 || status=$?
  grep -E "^stat::(number_of_executed_units|new_units_added)" "$scratch.log" || true
  grep -E "^#[0-9]+[[:space:]]+DONE" "$scratch.log" || true
  [ "$status" -eq 0 ] || tail -n 40 "$scratch.log"
  rm -rf "$scratch" "$scratch.log"
  if [ "$status" -ne 0 ]; then echo "fuzz: ${target}_fuzz failed" >&2; exit 1; fi
done
echo "fuzz: all targets ran without a crash"
