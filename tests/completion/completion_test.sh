#!/usr/bin/env bash
# The bash completion script `tape --bash-completion` makes, as bash runs it at a TAB: subcommands (nested
# ones too), each command's options, an option's value left to file names, and every subcommand that
# `tape --help` lists offered.
# Usage: completion_test.sh TAPE_BINARY
set -uo pipefail
tape=$1
script=$(mktemp "${TMPDIR:-/tmp}/tape-completion-XXXXXX")
trap 'rm -f "$script"' EXIT
"$tape" --bash-completion >"$script" || { echo "completion: tape --bash-completion failed" >&2; exit 1; }
# shellcheck disable=SC1090 # made just now
source "$script"
failed=0

# What a TAB after LINE offers: COMP_WORDS as bash splits the line, the last word the one completed.
offered() {
  local line=$1
  read -ra COMP_WORDS <<<"$line"
  [[ $line == *" " ]] && COMP_WORDS+=("")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _tape
  echo "${COMPREPLY[*]}"
}
expect() {
  local line=$1 want=$2 got
  got=$(offered "$line")
  if [ "$got" != "$want" ]; then
    echo "completion: '$line<TAB>' offers '$got', not '$want'" >&2
    failed=1
  fi
}

[[ $(complete -p tape) == *"-F _tape"* ]] || { echo "completion: no completion function for tape" >&2; failed=1; }
expect "tape dec" "decode"
expect "tape de" "decode devices"
expect "tape -v --max-errors 5 dec" "decode"
expect "tape decode --keep" "--keep-going"
expect "tape decode -o " ""
expect "tape decode part.ptp --charset " ""
expect "tape adapter " "$("$tape" adapter --help | sed -n '/^Subcommands:/,$s/^  \([a-z][a-z-]*\) .*/\1/p' | tr '\n' ' ' | sed 's/ $//')"
expect "tape adapter config --inv" "--invert"
expect "tape --vers" "--version"
expect "tape --bash" ""
expect "tape decode --he" "--help"

# Every subcommand of tape --help is offered, and nothing else.
listed=$("$tape" --help | sed -n '/^Subcommands:/,$s/^  \([a-z][a-z-]*\) .*/\1/p' | sort | tr '\n' ' ')
got=$(offered "tape " | tr ' ' '\n' | sort | tr '\n' ' ')
[ -n "$listed" ] || { echo "completion: tape --help lists no subcommands" >&2; failed=1; }
[ "$got" = "$listed" ] || { echo "completion: 'tape <TAB>' offers '$got'; tape --help lists '$listed'" >&2; failed=1; }

[ "$failed" -eq 0 ] && echo "completion: subcommands, options and option values complete as expected"
exit "$failed"
