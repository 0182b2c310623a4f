#!/usr/bin/env bash
# Runs one golden CLI case: tests/cli/cases/NAME.cmd is a shell snippet run in a fresh temporary
# folder holding a link `tapes` to the repository's tapes/, with $TAPE the binary under test.
# Its stdout, stderr and exit status must equal NAME.out, NAME.err and NAME.exit beside it.
# TAPE_UPDATE=1 writes those files from the run instead (review the diff before committing).
set -u
tape_bin=$(realpath "$1")
case_file=$(realpath "$2")
base=${case_file%.cmd}
repo=$(cd "$(dirname "$case_file")/../../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$repo/tapes" "$work/tapes"
(cd "$work" && TAPE="$tape_bin" bash -o pipefail "$case_file" >"$work/.out" 2>"$work/.err" </dev/null)
echo $? >"$work/.exit"
if [ "${TAPE_UPDATE:-}" = 1 ]; then
  cp "$work/.out" "$base.out"; cp "$work/.err" "$base.err"; cp "$work/.exit" "$base.exit"
  echo "updated $(basename "$base")"
  exit 0
fi
status=0
for part in out err exit; do
  if ! diff -u --label "expected $part" --label "actual $part" "$base.$part" "$work/.$part"; then status=1; fi
done
exit $status
