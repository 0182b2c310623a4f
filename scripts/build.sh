#!/usr/bin/env bash
# Configures and builds into build/ (the CLI ends up at build/bin/tape).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAPE_WERROR="$werror" >/dev/null
cmake --build build
