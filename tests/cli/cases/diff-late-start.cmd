# A read that begins inside the data (its leader and first 7 data frames not read) is a difference of the
# tape, also with --strict; said in one line besides the frames (issue 31, moshobo tape3 vs tape4). The
# tape has 100 blank frames of leader.
tail -c +108 tapes/gost-20999-format-example.iso.ptp > late.ptp
$TAPE diff tapes/gost-20999-format-example.iso.ptp late.ptp; echo "exit $?"
$TAPE diff --strict late.ptp tapes/gost-20999-format-example.iso.ptp; echo "exit $?"
