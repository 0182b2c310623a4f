#!/usr/bin/env bash
# Installs what the tests need (install-deps.sh all), checks the formatting (.clang-format), builds, then
# runs every test: units, CLI end-to-end, pseudo-terminal device tests, the USB adapter backends against
# umockdev, the fuzz corpus replay and the installed-package checks (build/); the guard on speed
# (bench/speed_guard.sh: start-up, decode, encode and lint against their targets); the USB adapter core
# cross-compiled for a Cortex-M0+ and the Raspberry Pi Pico firmware run on an emulated RP2040; every one
# of those tests again (but the emulated Pico's, minutes of real time) under AddressSanitizer and
# UndefinedBehaviorSanitizer (build-asan/); then a short fuzz run of each target (TAPE_FUZZ_SECONDS,
# default 5 s each: every target starts, takes its corpus and runs; the long run is its own command,
# `bash scripts/fuzz.sh 600`). It stops at the first stage that fails, naming it; exit status 1 then.
set -uo pipefail
cd "$(dirname "$0")/.."

stage() {
  local name=$1
  shift
  echo "test: $name"
  if ! "$@"; then
    echo "test: stopped: the $name stage failed (its output is above)" >&2
    exit 1
  fi
}

werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
# As many tests as cores side by side: none depends on being scheduled in time (scripts/stress-tests.sh
# checks that under load), but a shared CI machine gains nothing from more.
jobs=$(nproc)

# The USB adapter's core for its microcontroller (Cortex-M0+): it must build, and its size is shown; the
# Raspberry Pi Pico image (firmware/rp2040) within its budget, then run on an emulated RP2040 against the
# tape CLI (tests/adapter_pico_test.cpp, label rp2040; they skip, saying why, without node or rp2040js).
firmware() {
  local status=0 start=$SECONDS
  bash scripts/firmware-build.sh || status=$?
  [ "$status" -eq 77 ] && return 0 # no cross compiler: the script said so
  [ "$status" -eq 0 ] || return "$status"
  bash scripts/firmware-rp2040.sh build-firmware || return
  ctest --test-dir build --output-on-failure -j"$jobs" -L rp2040 || return
  echo "test: firmware stage took $((SECONDS - start)) s"
}

# -O1 -g1: half the compile time of -O2 -g, and still the file and line of every report. Any finding
# aborts the process, so the test fails; LeakSanitizer is on (ASan's default on Linux).
sanitize_build() {
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
    -DTAPE_SANITIZE=ON -DTAPE_BUILD_TESTS=ON -DTAPE_BUILD_BENCH=OFF -DTAPE_WERROR="$werror" >/dev/null &&
    cmake --build build-asan -j2
}
# The picture tests that run OpenCV in the test process (Scan.*, ScanReal.*) take GDAL in with it, whose
# dynamic TLS block GCC 12's LeakSanitizer misreads: its tracer dies at exit ("Tracer caught signal 11").
# They run apart with use_tls=0 (tests/lsan.supp then names what GDAL holds from its TLS); every other
# test keeps TLS scanned, without which glib's and umockdev's per-thread data would read as leaks.
sanitize_tests() {
  local lsan=suppressions="$PWD/tests/lsan.supp":print_suppressions=0 in_process_pictures='^Scan(Real)?\.'
  local -x ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1
  local -x UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  LSAN_OPTIONS=$lsan ctest --test-dir build-asan --output-on-failure -j"$jobs" -LE rp2040 \
    -E "$in_process_pictures" &&
    LSAN_OPTIONS=$lsan:use_tls=0 ctest --test-dir build-asan --output-on-failure -j"$jobs" -LE rp2040 \
      -R "$in_process_pictures"
}

stage dependencies bash scripts/install-deps.sh all
stage format bash scripts/check-format.sh
stage build bash scripts/build.sh
stage tests ctest --test-dir build --output-on-failure -j"$jobs" -LE rp2040
stage speed bash bench/speed_guard.sh build/bin/tape
stage firmware firmware
stage sanitize-build sanitize_build
stage sanitize-tests sanitize_tests
stage fuzz bash scripts/fuzz.sh "${TAPE_FUZZ_SECONDS:-5}"
echo "test: all passed"
