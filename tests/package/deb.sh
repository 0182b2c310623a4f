#!/usr/bin/env bash
# The .deb packages `cpack -G DEB` makes from the build: tape (the programs, man pages, bash completion,
# udev rule, code tables) and libtape-core-dev (the library), every file under /usr, each with the
# dependencies dpkg needs to install it; the tape program unpacked from its package runs.
# Usage: deb.sh BUILD_DIR VERSION
set -euo pipefail
build=$1 version=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/tape-deb-XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "package.deb: $*" >&2; exit 1; }

command -v dpkg-deb >/dev/null || fail "no dpkg-deb: not a Debian-like system"
command -v dpkg-shlibdeps >/dev/null || fail "no dpkg-shlibdeps (bash scripts/install-deps.sh test installs dpkg-dev)"
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack -G DEB failed"; }
arch=$(dpkg --print-architecture)
tape_deb=$work/tape_${version}_$arch.deb
dev_deb=$work/libtape-core-dev_${version}_$arch.deb
[ -f "$tape_deb" ] && [ -f "$dev_deb" ] || fail "cpack made $(cd "$work" && echo *.deb), not tape and libtape-core-dev"

# Fields: the version, and the libraries the programs are linked with among the dependencies.
field() { dpkg-deb --field "$1" "$2"; }
[ "$(field "$tape_deb" Version)" = "$version" ] || fail "tape: Version is '$(field "$tape_deb" Version)'"
depends=$(field "$tape_deb" Depends)
for lib in libc6 libstdc++6 libusb-1.0-0 libhidapi-hidraw0; do
  [[ ", $depends," == *", $lib "* || ", $depends," == *", $lib,"* ]] || fail "tape: Depends '$depends' lacks $lib"
done
dev_depends=$(field "$dev_deb" Depends)
for lib in libusb-1.0-0-dev libhidapi-dev; do
  [[ $dev_depends == *"$lib"* ]] || fail "libtape-core-dev: Depends '$dev_depends' lacks $lib"
done

# Contents: where a Debian system expects each file, and nothing outside /usr.
contents() { dpkg-deb --contents "$1" | awk '{print $6}' | sed 's|^\./|/|'; }
contents "$tape_deb" >"$work/tape.list"
contents "$dev_deb" >"$work/dev.list"
for f in /usr/bin/tape /usr/bin/tape-damage /usr/bin/tape-adapter-sim /usr/share/man/man1/tape.1.gz \
  /usr/share/man/man5/tape-image.5.gz /usr/share/man/man7/tape-devices.7.gz /usr/share/man/man7/tape-usb.7.gz \
  /usr/share/bash-completion/completions/tape /usr/lib/udev/rules.d/70-tape-adapter.rules \
  /usr/share/tape/eia-rs244.tab; do
  grep -qx "$f" "$work/tape.list" || fail "tape: no $f"
done
grep -qx "/usr/include/tape/code.hpp" "$work/dev.list" || fail "libtape-core-dev: no /usr/include/tape/code.hpp"
grep -q "/libtape_core.a$" "$work/dev.list" || fail "libtape-core-dev: no libtape_core.a"
grep -q "/pkgconfig/tape_core.pc$" "$work/dev.list" || fail "libtape-core-dev: no tape_core.pc"
outside=$(grep -v -e '^/usr/' -e '^/$' "$work/tape.list" "$work/dev.list" || true)
[ -z "$outside" ] || fail "files outside /usr: $outside"
if grep -q "/usr/bin/" "$work/dev.list"; then fail "libtape-core-dev holds programs"; fi

# Unpacked, the program runs and reads a bundled tape; the pkg-config file names /usr.
dpkg-deb -x "$tape_deb" "$work/root"
dpkg-deb -x "$dev_deb" "$work/root"
[ "$("$work/root/usr/bin/tape" --version)" = "tape $version" ] || fail "the packaged tape does not run"
"$work/root/usr/bin/tape" decode "$here/../../tapes/16k20f3s5-turning.iso.ptp" >/dev/null ||
  fail "the packaged tape does not decode a bundled tape"
if [ "${TAPE_HAVE_OPENCV:-OFF}" = ON ]; then  # the picture module, found beside the program
  grep -qx "/usr/$TAPE_PICTURE_MODULE_DIR/tape-pictures.so" "$work/tape.list" ||
    fail "tape: no /usr/$TAPE_PICTURE_MODULE_DIR/tape-pictures.so"
  "$work/root/usr/bin/tape" render "$here/../../tapes/16k20f3s5-turning.iso.ptp" -o "$work/drawn.png" ||
    fail "the packaged tape does not draw a bundled tape through its picture module"
fi
pc=$(find "$work/root/usr" -name tape_core.pc)
grep -qx "prefix=/usr" "$pc" || fail "tape_core.pc in libtape-core-dev does not say prefix=/usr"
echo "package.deb: tape and libtape-core-dev $version: files under /usr where Debian keeps them; Depends: $depends"
