#!/usr/bin/env bash
# Builds tape and the benchmarks in Release, runs the pipeline and codec benchmarks, and prints the
# issue's four figures in a table: decode/encode of a 128 MiB file against cat, peak memory on 1 MiB and
# 1 GiB, the codec core against memcpy, and `tape info` on the bundled sample 1000 times against cat.
# Takes a few minutes and about 2.3 GiB in TMPDIR. BUILD_DIR (default build-bench) picks the build;
# extra arguments go to both benchmark programs (e.g. --benchmark_filter=VsCat).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build-bench}
jobs=${JOBS:-$(nproc)}
# -O3 (Release) makes GCC 12 see false -Wrestrict overlaps inside libstdc++'s std::string: warn, not fail.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTAPE_WERROR=ON -DCMAKE_CXX_FLAGS=-Wno-error=restrict \
  >/dev/null
ninja -C "$build" -j "$jobs" tape pipeline_bench codec_bench >/dev/null

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "running pipeline_bench (a few minutes)..." >&2
"$build/bin/pipeline_bench" --benchmark_out="$out/pipeline.json" --benchmark_out_format=json "$@" >&2
echo "running codec_bench..." >&2
"$build/bin/codec_bench" --benchmark_filter='VsMemcpy' --benchmark_out="$out/codec.json" \
  --benchmark_out_format=json "$@" >&2

# Google Benchmark's JSON puts one "key": value a line; collect them per benchmark name.
awk '
  /"name":/ { name = $2; gsub(/[",]/, "", name); next }
  name != "" && /^ *"[A-Za-z_]+": / {
    key = $1; gsub(/[":]/, "", key); val = $0; sub(/^[^:]*: */, "", val); gsub(/[",]/, "", val)
    v[name, key] = val; seen[name] = 1
  }
  function find(prefix,   n) { for (n in seen) if (index(n, prefix) == 1) return n; return "" }
  function show(prefix, what,   n) {
    n = find(prefix)
    if (n == "") { printf "%-44s %s\n", what, "(not run)"; return 0 }
    if (v[n, "error_message"] != "") { printf "%-44s error: %s\n", what, v[n, "error_message"]; return 0 }
    return 1
  }
  END {
    printf "%-44s %10s %12s %8s %8s\n", "figure", "tape", "cat/memcpy", "ratio", "target"
    if (show("BM_DecodeVsCat", "1. decode 128 MiB ISO tape > /dev/null")) {
      n = find("BM_DecodeVsCat")
      printf "%-44s %8.1fms %10.1fms %8.2f %8s\n", "1. decode 128 MiB ISO tape > /dev/null", v[n, "tape_ms"], v[n, "cat_ms"], v[n, "ratio"], "<= 2"
    }
    if (show("BM_EncodeVsCat", "1. encode 128 MiB text > /dev/null")) {
      n = find("BM_EncodeVsCat")
      printf "%-44s %8.1fms %10.1fms %8.2f %8s\n", "1. encode 128 MiB text > /dev/null", v[n, "tape_ms"], v[n, "cat_ms"], v[n, "ratio"], "<= 2"
    }
    printf "%-44s %10s %12s %8s %8s\n", "2. peak RSS, MiB (exit status)", "1 MiB", "1 GiB", "", "<= 32"
    split("decode encode info blocks", cmd, " ")
    for (c = 1; c <= 4; ++c) {
      line = sprintf("     tape %s", cmd[c])
      for (s = 1; s <= 2; ++s) {
        n = find("BM_PeakRss/command:" (c - 1) "/MiB:" (s == 1 ? 1 : 1024) "/")
        if (n == "") cell[s] = "-"
        else cell[s] = sprintf("%.1f (%d)", v[n, "rss_MiB"], v[n, "exit"])
      }
      printf "%-44s %10s %12s\n", line, cell[1], cell[2]
    }
    split("Decode Encode", dir, " "); split("Decoder Encoder", core, " ")
    for (d = 1; d <= 2; ++d)
      for (s = 1; s <= 2; ++s) {
        piece = s == 1 ? "131072" : "67108864"
        what = sprintf("3. %s vs memcpy, GB/s (%s pieces)", core[d], s == 1 ? "128 KiB" : "64 MiB")
        if (show("BM_" dir[d] "VsMemcpy/" piece, what)) {
          n = find("BM_" dir[d] "VsMemcpy/" piece)
          printf "%-44s %10.2f %12.2f %8.2f %8s\n", what, v[n, "GBps"], v[n, "memcpy_GBps"], v[n, "vs_memcpy"], ">= 0.5"
        }
      }
    if (show("BM_InfoSampleVsCat", "4. tape info sample, 1000 runs: per run")) {
      n = find("BM_InfoSampleVsCat")
      printf "%-44s %8.0fus %10.0fus %8.2f\n", "4. tape info sample, 1000 runs: per run", v[n, "tape_us"], v[n, "cat_us"], v[n, "ratio"]
    }
  }' "$out/pipeline.json" "$out/codec.json"
