#!/usr/bin/env bash
# Installs the Debian packages the build and the tests need, when they are missing: as root directly,
# else through sudo. Without either it says what to run as root, and fails.
set -euo pipefail
packages=(cmake ninja-build g++ pkg-config libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
          libusb-1.0-0-dev libhidapi-dev clang-14 libclang-rt-14-dev clang-format-14 python3
          gcc-arm-none-eabi picolibc-arm-none-eabi libstdc++-arm-none-eabi-picolibc libxml2-utils chromium
          umockdev libumockdev-dev nlohmann-json3-dev
          # Reading pictures (tape scan, render to PNG): about 150 MB with what they pull in (GDAL for
          # imgcodecs), so a demo that only runs tape may go without: the build then says so.
          libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev)
command -v dpkg-query >/dev/null || {
  echo "install-deps: no dpkg-query: this is not a Debian-like system; install the equivalents of" >&2
  echo "  ${packages[*]}" >&2
  echo "with its package manager, then run this again" >&2
  exit 1
}
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
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
"${sudo[@]}" apt-get update -qq
# Through env: sudo drops the caller's environment.
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
