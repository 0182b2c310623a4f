#!/usr/bin/env bash
# Installs the Debian packages a purpose needs, when they are missing: as root directly, else through
# sudo. Without either it says what to run as root, and fails. apt's own output is shown.
#
# Usage: install-deps.sh [PURPOSE...]   (no purpose: all)
#   run       build and run the tape CLI (scripts/demo.sh)
#   features  the libraries of optional features (see below)
#   test      run and features, and what the tests need (scripts/test.sh, scripts/build.sh, scripts/fuzz.sh);
#             also the npm package rp2040js, pinned in tests/rp2040/package-lock.json (npm ci there)
#   firmware  the Cortex-M0+ cross toolchain (scripts/firmware-build.sh)
#   all       all of these
#
# Where a new package goes: `run` when the CLI cannot be built or used without it (man-db for `man tape`,
# bash-completion to load its completion); `features` when only one optional feature uses it, and CMake
# builds that feature only when the library is found, the command answering "built without LIBRARY"
# otherwise (so the demo stays small); `test` when only tests, the sanitizers, the fuzzers or the package
# checks use it. One package a line. Every program a test or script calls comes from one of these or from
# a fresh Debian (tests/deps/programs_packaged.py checks it).
set -euo pipefail

run=(
  cmake
  ninja-build
  g++
  pkg-config
  libcli11-dev
  nlohmann-json3-dev
  libusb-1.0-0-dev
  libhidapi-dev
  nettle-dev
  man-db
  bash-completion
)
features=(
  libtomlplusplus-dev
  libopencv-core-dev
  libopencv-imgproc-dev
  libopencv-imgcodecs-dev
  libcairo2-dev
)
test=(
  libgtest-dev
  libgmock-dev
  libbenchmark-dev
  python3
  libxml2-utils
  chromium
  umockdev
  libumockdev-dev
  clang-14
  libclang-rt-14-dev
  clang-format-14
  dpkg-dev
  file
  xxd
  stress-ng
  nodejs
)
firmware=(
  gcc-arm-none-eabi
  picolibc-arm-none-eabi
  libstdc++-arm-none-eabi-picolibc
)

usage() {
  sed -n '5,10s/^# \{0,1\}//p' "$0"
}

packages=()
rp2040js=no
[ $# -eq 0 ] && set -- all
for purpose in "$@"; do
  case $purpose in
    run) packages+=("${run[@]}") ;;
    features) packages+=("${features[@]}") ;;
    test) packages+=("${run[@]}" "${features[@]}" "${test[@]}") rp2040js=yes ;;
    firmware) packages+=("${firmware[@]}") ;;
    all) packages+=("${run[@]}" "${features[@]}" "${test[@]}" "${firmware[@]}") rp2040js=yes ;;
    -h | --help)
      usage
      exit 0
      ;;
    *)
      echo "install-deps: no purpose '$purpose'" >&2
      usage >&2
      exit 2
      ;;
  esac
done

command -v dpkg-query >/dev/null || {
  echo "install-deps: no dpkg-query: this is not a Debian-like system; install the equivalents of" >&2
  echo "  ${packages[*]}" >&2
  echo "with its package manager, then run this again" >&2
  exit 1
}
missing=()
for p in "${packages[@]}"; do
  [[ " ${missing[*]} " == *" $p "* ]] && continue
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Debian's nodejs comes without npm (a package of its own); NodeSource's brings it along.
[ "$rp2040js" = yes ] && ! command -v npm >/dev/null && missing+=(npm)

# The emulated RP2040 the firmware tests run on (tests/rp2040): the versions in its lock file.
install_rp2040js() {
  [ "$rp2040js" = yes ] || return 0
  [ -f tests/rp2040/node_modules/rp2040js/package.json ] && return 0
  (cd tests/rp2040 && npm ci --no-audit --no-fund)
}
cd "$(dirname "$0")/.."
if [ ${#missing[@]} -eq 0 ]; then
  install_rp2040js
  exit 0
fi
sudo=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || {
    echo "install-deps: missing packages: ${missing[*]}" >&2
    echo "install-deps: not root and no sudo to install them; as root, run:" >&2
    echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
  }
  sudo=(sudo)
fi
echo "install-deps: installing ${missing[*]}" >&2
"${sudo[@]}" apt-get update
# Through env: sudo drops the caller's environment. The downloaded .deb files are not kept: they would
# take as much disk again as the packages they hold.
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
  -o APT::Keep-Downloaded-Packages=false "${missing[@]}"
install_rp2040js
