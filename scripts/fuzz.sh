#!/usr/bin/env bash
# Builds the libFuzzer targets with clang-14 and runs each for a bounded time (default 30 s).
# New inputs go to a scratch folder; the committed corpus in tests/fuzz/corpus/ is only read.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
bash scripts/install-deps.sh
CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTAPE_BUILD_FUZZ=ON -DTAPE_BUILD_TESTS=OFF -DTAPE_BUILD_BENCH=OFF >/dev/null
for target in decode loader; do
  cmake --build build-fuzz --target "${target}_fuzz"
  scratch=$(mktemp -d)
  echo "fuzz: ${target}_fuzz for ${seconds} s"
  status=0
  build-fuzz/bin/${target}_fuzz -max_total_time="$seconds" -print_final_stats=1 \
    "$scratch" "tests/fuzz/corpus/$target" >"$scratch.log" 2>&1 || status=$?
  grep -E "^stat::(number_of_executed_units|new_units_added)" "$scratch.log" || true
  [ "$status" -eq 0 ] || tail -n 40 "$scratch.log"
  rm -rf "$scratch" "$scratch.log"
  if [ "$status" -ne 0 ]; then echo "fuzz: ${target}_fuzz failed" >&2; exit 1; fi
done
echo "fuzz: all targets ran without a crash"
