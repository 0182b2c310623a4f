#!/usr/bin/env bash
# The main job on a bundled sample: build, then read the 16К20Ф3С5 tape back and show what is on it.
# The build steps are scripts/build.sh's, each announced: a first build takes minutes, and a silent
# terminal for that long looks like a hang.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "demo: installing dependencies…"
bash scripts/install-deps.sh
echo "demo: configuring…"
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# Quiet unless it fails: then its whole output says why.
if ! cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAPE_WERROR="$werror" >"$log" 2>&1; then
  cat "$log" >&2
  echo "demo: configuring failed" >&2
  exit 1
fi
echo "demo: building (a first build takes a few minutes)…"
cmake --build build
tape=build/bin/tape
sample=tapes/16k20f3s5-turning.iso.ptp
echo "== tape info $sample"
$tape info "$sample"
echo "== tape decode $sample"
$tape -v decode "$sample"
echo "== tape show $sample (first frames)"
$tape show "$sample" | sed -n '1,2p;99,114p'
