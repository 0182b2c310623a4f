#!/usr/bin/env bash
# The main job on a bundled sample: build, then read the 16К20Ф3С5 tape back and show what is on it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
tape=build/bin/tape
sample=tapes/16k20f3s5-turning.iso.ptp
echo "== tape info $sample"
$tape info "$sample"
echo "== tape decode $sample"
$tape -v decode "$sample"
echo "== tape show $sample (first frames)"
$tape show "$sample" | sed -n '1,2p;99,114p'
