#!/usr/bin/env bash
# Installs the built tree into a temporary prefix, then checks what a user gets there: the programs, their
# man pages (man finds them from PATH), bash completion, the udev rule and the code tables where the
# distribution expects them, under the prefix and nowhere else; and for the library: tape_core.pc naming
# that prefix, every public header compiling on its own, and the consumer program in consumer/ built and
# run twice, through find_package(tape_core) and through `pkg-config --cflags --libs tape_core`.
# Usage: run.sh BUILD_DIR LIBDIR INCLUDEDIR VERSION CXX GENERATOR [MAKE_PROGRAM]
# (LIBDIR and INCLUDEDIR as GNUInstallDirs gives them, relative to the prefix); the environment gives
# TAPE_BINDIR, TAPE_MANDIR, TAPE_DATADIR the same way, and TAPE_UDEV_RULES_DIR (relative, or absolute for
# a system install).
set -euo pipefail
build=$1 libdir=$2 includedir=$3 version=$4 cxx=$5 generator=$6 make_program=${7:-}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/tape-package-XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
fail() { echo "package: $*" >&2; exit 1; }
# Runs a step quietly; its output is shown when it fails.
step() {
  local name=$1
  shift
  "$@" >"$work/step.log" 2>&1 || { cat "$work/step.log" >&2; fail "$name failed"; }
}

# Staged (DESTDIR), as a distribution installs: what lands outside the prefix shows, and stays in $work.
stage=$work/stage
step "cmake --install" env DESTDIR="$stage" cmake --install "$build" --prefix "$prefix"
mkdir -p "$(dirname "$prefix")"
mv "$stage$prefix" "$prefix"
udev_rule=$prefix/$TAPE_UDEV_RULES_DIR/70-tape-adapter.rules
[[ $TAPE_UDEV_RULES_DIR == /* ]] && udev_rule=$stage$TAPE_UDEV_RULES_DIR/70-tape-adapter.rules
[ -f "$udev_rule" ] || fail "no udev rule at ${udev_rule#"$stage"}"
[ -z "$(find "$stage" -type f -not -path "$(dirname "$udev_rule")/*")" ] ||
  fail "installed outside the prefix: $(find "$stage" -type f | sed "s|^$stage||" | tr '\n' ' ')"

# The programs, as a user with the prefix's bin on PATH has them.
export PATH=$prefix/$TAPE_BINDIR:$PATH
for program in tape tape-damage tape-adapter-sim; do
  [ "$(command -v "$program")" = "$prefix/$TAPE_BINDIR/$program" ] || fail "$program is not in $prefix/$TAPE_BINDIR"
done
[ "$(tape --version)" = "tape $version" ] || fail "tape --version says '$(tape --version)'"
step "tape decode of a bundled tape" tape decode "$here/../../tapes/16k20f3s5-turning.iso.ptp"
# The picture module beside the programs, where the installed tape finds it and draws a tape with it.
if [ "${TAPE_HAVE_OPENCV:-OFF}" = ON ]; then
  [ -f "$prefix/$TAPE_PICTURE_MODULE_DIR/tape-pictures.so" ] || fail "no $TAPE_PICTURE_MODULE_DIR/tape-pictures.so"
  step "tape render of a bundled tape to PNG" tape render "$here/../../tapes/16k20f3s5-turning.iso.ptp" \
    -o "$work/drawn.png"
  rm -f "$work/drawn.png"
fi
for page in man1/tape.1 man1/tape-plot.1 man1/tape-damage.1 man5/tape-image.5 man7/tape-devices.7 man7/tape-usb.7; do
  [ -f "$prefix/$TAPE_MANDIR/$page.gz" ] || fail "no $TAPE_MANDIR/$page.gz"
done
command -v man >/dev/null || fail "man is not installed (bash scripts/install-deps.sh test installs man-db)"
found=$(env -u MANPATH man -w tape 2>&1) || true
[ "$found" = "$prefix/$TAPE_MANDIR/man1/tape.1.gz" ] || fail "man -w tape finds '$found', not the installed page"
completion=$prefix/$TAPE_DATADIR/bash-completion/completions/tape
[ -f "$completion" ] || fail "no $TAPE_DATADIR/bash-completion/completions/tape"
bash -c "source '$completion' && complete -p tape" >/dev/null 2>&1 || fail "$completion sets no completion for tape"
for table in eia-rs244.tab ita2.tab mtk2.tab; do
  [ -f "$prefix/$TAPE_DATADIR/tape/$table" ] || fail "no $TAPE_DATADIR/tape/$table"
done

command -v pkg-config >/dev/null || fail "pkg-config is not installed (bash scripts/install-deps.sh installs it)"
export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
[ -f "$PKG_CONFIG_PATH/tape_core.pc" ] || fail "no $PKG_CONFIG_PATH/tape_core.pc"
check_variable() {
  local got
  got=$(pkg-config --variable="$1" tape_core)
  [ "$got" = "$2" ] || fail "tape_core.pc: $1 is '$got', not '$2'"
}
check_variable prefix "$prefix"
check_variable libdir "$prefix/$libdir"
check_variable includedir "$prefix/$includedir"
[ "$(pkg-config --modversion tape_core)" = "$version" ] || fail "tape_core.pc: version is not $version"
[ -f "$prefix/$libdir/libtape_core.a" ] || fail "no $prefix/$libdir/libtape_core.a"

headers=("$prefix/$includedir"/tape/*.hpp)
[ -f "${headers[0]}" ] || fail "no headers in $prefix/$includedir/tape"
# Each header alone in a file of its own, two compilers at a time; a failure names the file.
mkdir "$work/headers"
for header in "${headers[@]}"; do
  echo "#include \"tape/${header##*/}\"" >"$work/headers/${header##*/}.cpp"
done
# shellcheck disable=SC2046 # the flags are words
step "every public header on its own" xargs -0 -n 1 -P 2 "$cxx" -fsyntax-only -Wall -Wextra -Wpedantic -Werror \
  $(pkg-config --cflags tape_core) < <(printf '%s\0' "$work/headers"/*.cpp)

# The library's users get none of the system headers it uses privately (termios macros such as B9600).
if grep -l '#include <termios.h>' "${headers[@]}" >"$work/termios.txt"; then
  fail "public headers include <termios.h>: $(tr '\n' ' ' <"$work/termios.txt")"
fi

# Through CMake: asking for this version finds the package here, and a later major version is refused.
cmake_options=(-G "$generator" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix"
               -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_BUILD_TYPE=Release)
[ -n "$make_program" ] && cmake_options+=(-DCMAKE_MAKE_PROGRAM="$make_program")
step "configuring the consumer" cmake -S "$here/consumer" -B "$work/cmake-build" "${cmake_options[@]}" \
  -DTAPE_WANT_VERSION="$version"
grep -q "tape_core $version from $prefix/" "$work/step.log" || { cat "$work/step.log" >&2; fail "tape_core not found in $prefix"; }
step "building the consumer" cmake --build "$work/cmake-build" -j2
step "running the consumer (CMake)" "$work/cmake-build/consumer"
major=${version%%.*}
if cmake -S "$here/consumer" -B "$work/cmake-too-new" "${cmake_options[@]}" -DTAPE_WANT_VERSION=$((major + 1)).0 \
  >"$work/step.log" 2>&1; then
  fail "find_package(tape_core $((major + 1)).0) accepted version $version"
fi

# Through pkg-config, with nothing but its flags.
# shellcheck disable=SC2046 # the flags are words
step "building the consumer (pkg-config)" "$cxx" -Wall -Wextra -Wpedantic -Werror "$here/consumer/main.cpp" \
  $(pkg-config --cflags --libs tape_core) -o "$work/consumer-pc"
step "running the consumer (pkg-config)" "$work/consumer-pc"
echo "package: installed into a temporary prefix and nowhere else; the programs, man pages, completion, udev rule"
echo "package: and tables in place; the library found by CMake and by pkg-config; the consumer ran"
