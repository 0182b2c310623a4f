#!/usr/bin/env bash
# The guard on tape's speed that CI runs after the tests: each figure of the table below, measured as
# CPU time (user + system, the least of RUNS runs, so that a loaded machine counts as little as it can),
# against a plain read of the same bytes (dd bs=128K) timed in the same run, turn about. It prints every
# figure and fails (exit 1) when one is over its limit: twice its target, so that noise does not fail a
# submission and a regression like the one that made decode 40 times a read does.
#
#   figure                                     target          limit here
#   tape --version (any command's fixed cost)  <= 10 ms CPU    20 ms
#   tape decode, 128 MiB ISO tape              <= 2x the read  4x
#   tape encode, the same program              <= 3x the read  6x
#   tape lint, a 200 000-block program         <= 0.1 s CPU    0.2 s
#
# Usage: bench/speed_guard.sh [TAPE]   (default build/bin/tape; RUNS, 7 unless set, and TMPDIR as usual). The files
# (about 260 MB) are made in a temporary folder, removed at the end. Needs bash, awk and dd only.
set -euo pipefail
tape=${1:-build/bin/tape}
runs=${RUNS:-7}
[ -x "$tape" ] || {
  echo "speed-guard: no tape program at $tape (build it first)" >&2
  exit 2
}
dir=$(mktemp -d "${TMPDIR:-/tmp}/tape-speed-guard.XXXXXX")
trap 'rm -rf "$dir"' EXIT

# A part program as a machinist writes one: numbered blocks of G, X, Z and F words, now and then S and
# M words or a comment; 1 MiB of them made once, repeated to 128 MiB between '%' and M02.
awk 'BEGIN { srand(7); while (bytes < 1048576) { n++
  line = sprintf("N%04d G0%d X%+09d Z%+08d F%d", n % 10000, int(rand() * 4), int(rand() * 1e8), int(rand() * 1e7),
                 10 + int(rand() * 20000))
  if (n % 7 == 0) line = line sprintf(" S%d M0%d", 100 + int(rand() * 2900), 3 + int(rand() * 7))
  if (n % 13 == 0) line = line " (FINISH PASS)"
  print line; bytes += length(line) + 1 } }' >"$dir/blocks.txt"
{
  echo %
  for _ in $(seq 128); do cat "$dir/blocks.txt"; done
  printf 'N9999 M02\n%%\n'
} >"$dir/program.txt"
"$tape" encode "$dir/program.txt" -o "$dir/program.ptp"
# A 200 000-block mill program, every block numbered in order and clean: lint finds nothing to say.
awk 'BEGIN { srand(3); print "%"; print "O1000"; print "N1 G90 G54 G00 X0 Y0 Z50."
  for (n = 2; n <= 200000; n++) printf "N%d G01 X%.3f Y%.3f F%d\n", n, rand() * 500, rand() * 300, 100 + int(rand() * 900)
  print "M30"; print "%" }' >"$dir/lint.nc"

# CPU seconds (user + system) of one run of the command, its output thrown away.
cpu() {
  local TIMEFORMAT='%3U %3S' t
  t=$({ time "$@" >/dev/null 2>&1; } 2>&1) || {
    echo "speed-guard: failed: $*" >&2
    exit 1
  }
  awk -v t="$t" 'BEGIN { split(t, p, " "); printf "%.4f", p[1] + p[2] }'
}
least() { printf '%s\n' "$@" | sort -g | sed -n 1p; }

failed=0
# figure NAME LIMIT UNIT COMMAND...: with UNIT "x", against dd of the command's last argument.
figure() {
  local name=$1 limit=$2 unit=$3
  shift 3
  local input=${*: -1} tape_s=() read_s=() value
  for _ in $(seq "$runs"); do
    tape_s+=("$(cpu "$@")")
    [ "$unit" = x ] && read_s+=("$(cpu dd if="$input" of=/dev/null bs=128K)")
  done
  local t r
  t=$(least "${tape_s[@]}")
  if [ "$unit" = x ]; then
    r=$(least "${read_s[@]}")
    value=$(awk -v t="$t" -v r="$r" 'BEGIN { printf "%.2f", t / (r > 0.001 ? r : 0.001) }')
    printf '%-44s %8.3f s  read %6.3f s  %6sx  limit %sx\n' "$name" "$t" "$r" "$value" "$limit"
  else
    value=$t
    printf '%-44s %8.3f s  %26s limit %s s\n' "$name" "$t" "" "$limit"
  fi
  if awk -v v="$value" -v l="$limit" 'BEGIN { exit !(v > l) }'; then
    echo "speed-guard: $name: $value over the limit $limit" >&2
    failed=1
  fi
}

echo "speed-guard: CPU time, the least of $runs runs ($(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg))"
figure "tape --version" 0.020 s "$tape" --version
figure "tape decode, 128 MiB ISO tape" 4 x "$tape" decode "$dir/program.ptp"
figure "tape encode, 128 MiB program" 6 x "$tape" encode "$dir/program.txt"
figure "tape lint, 200 000 blocks" 0.2 s "$tape" lint "$dir/lint.nc"
[ "$failed" = 0 ] && echo "speed-guard: every figure within its limit"
exit "$failed"
