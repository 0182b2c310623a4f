#!/usr/bin/env bash
# Installs the built tree into a temporary prefix, then checks what a user of the library gets there:
# tape_core.pc naming that prefix, every public header compiling on its own, and the consumer
# program in consumer/ built and run twice, through
# find_package(tape_core) and through `pkg-config --cflags --libs tape_core`.
# Usage: run.sh BUILD_DIR LIBDIR INCLUDEDIR VERSION CXX GENERATOR [MAKE_PROGRAM]
# (LIBDIR and INCLUDEDIR as GNUInstallDirs gives them, relative to the prefix.)
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

step "cmake --install" cmake --install "$build" --prefix "$prefix"

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
# shellcheck disable=SC2046 # the flags are words
for header in "${headers[@]}"; do
  echo "#include \"tape/${header##*/}\"" >"$work/one.cpp"
  step "${header##*/} on its own" "$cxx" -fsyntax-only -Wall -Wextra -Wpedantic -Werror \
    $(pkg-config --cflags tape_core) "$work/one.cpp"
done

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
echo "package: installed into a temporary prefix; found by CMake and by pkg-config; the consumer ran"
