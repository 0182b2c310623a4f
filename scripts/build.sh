#!/usr/bin/env bash
# Configures and builds everything into build/, tests and benchmarks included (the CLI ends up at
# build/bin/tape). Installs what that needs first (install-deps.sh test).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh test
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
# Tests and benchmarks on, whatever an earlier configuration (the demo's) said.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAPE_WERROR="$werror" -DTAPE_BUILD_TESTS=ON \
  -DTAPE_BUILD_BENCH=ON >/dev/null
cmake --build build
