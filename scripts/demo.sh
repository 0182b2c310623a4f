#!/usr/bin/env bash
# The main job on a bundled sample: installs what the CLI needs (install-deps.sh run: no test, firmware
# or optional-feature packages), builds the tape program alone, then reads the 16К20Ф3С5 tape back and
# shows what is on it. Each step is announced and shows its progress: a silent terminal for minutes
# looks like a hang.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "demo: installing dependencies (scripts/install-deps.sh run)…"
bash scripts/install-deps.sh run
echo "demo: configuring…"
options=()
# A first configuration leaves out the tests and benchmarks, whose libraries the demo does not install,
# and builds -O2 without debug information: a third less compile time and a tenth of the disk of
# RelWithDebInfo (scripts/build.sh's, which a later scripts/test.sh switches build/ to). An existing build/
# keeps its own settings.
if [ ! -f build/CMakeCache.txt ]; then
  werror=OFF
  [ "${CI:-}" = "true" ] && werror=ON
  options=(-G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" -DTAPE_WERROR="$werror"
           -DTAPE_BUILD_TESTS=OFF -DTAPE_BUILD_BENCH=OFF)
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# Quiet unless it fails: then its whole output says why.
if ! cmake -S . -B build "${options[@]}" >"$log" 2>&1; then
  cat "$log" >&2
  echo "demo: configuring failed" >&2
  exit 1
fi
echo "demo: building the tape program (a first build takes a few minutes)…"
cmake --build build --target tape
tape=build/bin/tape
sample=tapes/16k20f3s5-turning.iso.ptp
echo "== tape info $sample"
$tape info "$sample"
echo "== tape decode $sample"
$tape -v decode "$sample"
echo "== tape show $sample (first frames)"
$tape show "$sample" | sed -n '1,2p;99,114p'
echo "demo: done; the CLI is build/bin/tape (README.md, Install, puts it on your PATH)"
