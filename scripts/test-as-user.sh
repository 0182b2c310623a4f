#!/usr/bin/env bash
# Runs the whole suite built in build/ (scripts/build.sh, scripts/test.sh) again as a user who is not
# root, with a temporary directory (TMPDIR) and a home of its own, then checks that the tests touched
# nothing outside the build tree: no file of that user's newer than the run's start anywhere else, and
# TMPDIR and the home empty. As root (CI) it runs as the user tape-test, created when absent, who owns
# build/ for the run; as anyone else, as that user.
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
build=$repo/build
say() { echo "test-as-user: $*" >&2; }
[ -f "$build/CTestTestfile.cmake" ] || { say "no tests built in build/ (bash scripts/build.sh builds them)"; exit 1; }

run=$(mktemp -d "/tmp/tape-as-user.XXXXXX")
chmod 755 "$run"
mkdir "$run/tmp" "$run/home"
stamp=$run/stamp
touch "$stamp"
undo=()
cleanup() {
  local i
  for ((i = ${#undo[@]} - 1; i >= 0; i--)); do eval "${undo[i]}" || true; done
  rm -rf "$run"
}
trap cleanup EXIT

as_user=()
user=$(id -un)
if [ "$(id -u)" -eq 0 ]; then
  user=tape-test
  if ! id "$user" >/dev/null 2>&1; then
    useradd --system --no-create-home --home-dir /nonexistent --shell /usr/sbin/nologin "$user"
    say "created the user $user"
  fi
  chown "$user:" "$run/tmp" "$run/home"
  # build/ is the user's for the run, and its owner's again after.
  owner=$(stat -c %u:%g "$build")
  chown -R "$user:" "$build"
  undo+=("chown -R $owner '$build'")
  # The user must reach the sources: a folder above them that others may not enter is opened (o+x) for
  # the run, as a CI clone in /root would need.
  dir=$repo
  while [ "$dir" != / ]; do
    if ! runuser -u "$user" -- test -x "$dir"; then
      undo+=("chmod $(stat -c %a "$dir") '$dir'")
      chmod o+x "$dir"
      say "opened $dir to others (o+x) for the run"
    fi
    dir=$(dirname "$dir")
  done
  as_user=(runuser -u "$user" --)
fi

say "the suite as $user, TMPDIR=$run/tmp, HOME=$run/home"
status=0
if ! "${as_user[@]}" env -i PATH="$PATH" LANG=C.UTF-8 HOME="$run/home" TMPDIR="$run/tmp" ${CI:+CI=$CI} \
  ctest --test-dir "$build" --output-on-failure -j2; then
  say "the suite failed as $user (above)"
  status=1
fi

# What the user made or changed outside the build tree and the run's folder; /proc and /sys are no files,
# wherever they are mounted (a chroot's too). Folders find may not read are not the tests' doing: its
# status is not the check's, what it prints is.
left=$( (find / \( -path /proc -o -path /sys -o -fstype proc -o -fstype sysfs -o -path "$build" -o -path "$run" \) \
  -prune -o -user "$user" -newer "$stamp" -print 2>/dev/null || true) | head -n 20)
tmp_left=$( (find "$run/tmp" "$run/home" -mindepth 1 -maxdepth 2 || true) | head -n 20)
if [ -n "$left" ]; then
  say "the tests left outside the build tree:"
  echo "$left" >&2
  status=1
fi
if [ -n "$tmp_left" ]; then
  say "the tests left in their TMPDIR or home:"
  echo "$tmp_left" >&2
  status=1
fi
[ -z "$left$tmp_left" ] && say "nothing left outside the build tree; TMPDIR and home empty"
[ "$status" -eq 0 ] && say "passed as $user"
exit "$status"
