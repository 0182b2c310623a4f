#!/usr/bin/env bash
# tape archive's figures (issue 34): a bag of 5 reads of a 10^6-frame tape created, in CPU seconds (target
# <= 3 s), and verified: its checksums (--fast, target <= 1 s) and with every restoration made again. Each
# figure is the least of RUNS runs (default 3), user + system time; the reads are a generated part program
# punched by tape encode and damaged by tape-damage (1% of the frames each, seeds 1-5), made once in a
# temporary folder (about 10 MB) that is removed at the end. Needs bash, awk, sha256sum.
#
# Usage: bench/archive_bench.sh [BUILD_DIR]   (default build; it must hold bin/tape and bin/tape-damage)
set -euo pipefail
build=${1:-build}
tape=$build/bin/tape
damage=$build/bin/tape-damage
runs=${RUNS:-3}
for p in "$tape" "$damage"; do
  [ -x "$p" ] || {
    echo "archive-bench: no $p (build tape and tape-damage first)" >&2
    exit 2
  }
done
dir=$(mktemp -d "${TMPDIR:-/tmp}/tape-archive-bench.XXXXXX")
trap 'rm -rf "$dir"' EXIT

# A program of numbered blocks, cut so that its tape is 10^6 frames with leader and trailer.
awk 'BEGIN { srand(11); print "%"; while (bytes < 999000) { n++
  line = sprintf("N%04d G01 X%+08d Z%+07d F%d", n % 10000, int(rand() * 1e7), int(rand() * 1e6), 10 + int(rand() * 900))
  print line; bytes += length(line) + 1 } print "M02"; print "%" }' >"$dir/program.txt"
"$tape" encode "$dir/program.txt" -o "$dir/tape.ptp"
reads=()
for seed in 1 2 3 4 5; do
  "$damage" "$dir/tape.ptp" --seed "$seed" --damage 0.01 -o "$dir/read.$seed"
  reads+=(--read "$dir/read.$seed")
done
frames=$(stat -c %s "$dir/tape.ptp")

cpu() {
  local TIMEFORMAT='%3U %3S' t
  t=$({ time "$@" >/dev/null 2>&1; } 2>&1) || true # a restoration with doubts exits 1: still a bag
  awk -v t="$t" 'BEGIN { split(t, p, " "); printf "%.3f", p[1] + p[2] }'
}
least() { printf '%s\n' "$@" | sort -g | sed -n 1p; }

create=() fast=() full=()
for i in $(seq "$runs"); do
  rm -rf "$dir/bag"
  create+=("$(cpu "$tape" archive create "$dir/bag" "${reads[@]}")")
  fast+=("$(cpu "$tape" archive verify "$dir/bag" --fast)")
  full+=("$(cpu "$tape" archive verify "$dir/bag")")
done
"$tape" archive verify "$dir/bag" --fast
bytes=$(du -sb "$dir/bag/data" | cut -f1)
echo "archive-bench: 5 reads of $frames frames, a payload of $bytes bytes; CPU s, the least of $runs runs ($(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg))"
printf '%-44s %8s s  target %s s\n' "tape archive create" "$(least "${create[@]}")" 3
printf '%-44s %8s s  target %s s\n' "tape archive verify --fast (checksums)" "$(least "${fast[@]}")" 1
printf '%-44s %8s s\n' "tape archive verify (and restoring again)" "$(least "${full[@]}")"
