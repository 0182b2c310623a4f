#!/usr/bin/env bash
# Builds, then runs every test: units, CLI end-to-end, fuzz corpus replay, and a bounded fuzz run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
bash scripts/fuzz.sh "${TAPE_FUZZ_SECONDS:-30}"
