#!/usr/bin/env bash
# Runs tests of build/ again and again beside a CPU hog (stress-ng), and counts the failures: a test that
# passes only when its process is scheduled in time fails here. Every run's failures are named, then the
# sum. Exit 1 when any run failed.
#
# Usage: stress-tests.sh [-n RUNS] [-j JOBS] [-c HOG_CPUS] [-t TREE] [REGEX | all]
#   REGEX   the ctest tests to run (ctest -R); default: the device tests that hang up, stop or time a
#           line (pseudo-terminals, tape emulate/read/receive/feed/punch, the DNC service)
#   all     the whole suite
#   -n 20   runs   -j 2 ctest's parallel jobs   -c 2 stress-ng CPU workers   -t build  the build tree
# Not part of every CI run (.ci/run): 20 runs of the device tests take some 20 min on two loaded cores, the
# whole suite five times about an hour (`bash scripts/stress-tests.sh -n 5 -j 4 all`).
set -uo pipefail
cd "$(dirname "$0")/.."
runs=20 jobs=2 hog=2 tree=build
while getopts "n:j:c:t:" opt; do
  case $opt in
    n) runs=$OPTARG ;;
    j) jobs=$OPTARG ;;
    c) hog=$OPTARG ;;
    t) tree=$OPTARG ;;
    *)
      sed -n '6,10s/^# \{0,1\}//p' "$0" >&2
      exit 2
      ;;
  esac
done
shift $((OPTIND - 1))
regex=${1:-'^(CliEmulate|CliRead|CliReceive|CliFeed|CliPunch|DevicePty|DncService)\.'}
select=(-R "$regex")
[ "$regex" = all ] && select=()
[ -f "$tree/CTestTestfile.cmake" ] || {
  echo "stress-tests: no tests in $tree/: build them first (scripts/build.sh)" >&2
  exit 2
}
command -v stress-ng >/dev/null || {
  echo "stress-tests: no stress-ng: bash scripts/install-deps.sh test installs it" >&2
  exit 2
}

work=$(mktemp -d)
hog_pid=
stop_hog() {
  [ -n "$hog_pid" ] && kill "$hog_pid" 2>/dev/null && wait "$hog_pid" 2>/dev/null
  rm -rf "$work"
}
trap stop_hog EXIT
# The hog runs until this script ends (killed by its own pid): the load is there from the first run on.
stress-ng --cpu "$hog" --quiet >/dev/null 2>&1 &
hog_pid=$!

total=0 failed_runs=0
: >"$work/failed"
start=$(date +%s)
for ((run = 1; run <= runs; run++)); do
  t0=$(date +%s)
  ctest --test-dir "$tree" -j "$jobs" "${select[@]}" --output-on-failure >"$work/log" 2>&1
  status=$?
  count=$(sed -n 's/.*tests passed, [0-9]* tests failed out of \([0-9]*\)/\1/p' "$work/log")
  [ -n "$count" ] || count=$(sed -n 's/^100% tests passed, 0 tests failed out of \([0-9]*\)/\1/p' "$work/log")
  total=$((total + ${count:-0}))
  failures=$(sed -n '/The following tests FAILED:/,$s/^[[:space:]]*[0-9]* - \([^ ]*\) .*/\1/p' "$work/log")
  echo "stress-tests: run $run/$runs: ${count:-?} tests, $(echo -n "$failures" | grep -c .) failed, $(($(date +%s) - t0)) s"
  if [ "$status" -ne 0 ]; then
    failed_runs=$((failed_runs + 1))
    [ -n "$failures" ] || failures="(ctest status $status)"
    echo "$failures" >>"$work/failed"
    echo "$failures" | sed 's/^/stress-tests:   failed: /'
    cp "$work/log" "$tree/stress-tests-run$run.log"
    echo "stress-tests:   its output: $tree/stress-tests-run$run.log"
  fi
done
echo "stress-tests: $runs runs of ${regex} beside stress-ng --cpu $hog, ctest -j $jobs, $(nproc) cores:" \
  "$total test runs, $(grep -c . "$work/failed") failures in $failed_runs runs, $(($(date +%s) - start)) s"
sort "$work/failed" | uniq -c | sort -rn | sed 's/^/stress-tests:   /'
[ "$failed_runs" -eq 0 ]
