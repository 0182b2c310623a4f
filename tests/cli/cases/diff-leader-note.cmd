# Leaders of different length are no difference of the tape: a note says so (exit 0); --strict counts
# them. A tape holding the same program twice diffs against itself.
head -c 5 tapes/gost-20999-format-example.iso.ptp > longer.ptp
cat tapes/gost-20999-format-example.iso.ptp >> longer.ptp
$TAPE diff tapes/gost-20999-format-example.iso.ptp longer.ptp; echo "exit $?"
$TAPE diff --strict tapes/gost-20999-format-example.iso.ptp longer.ptp; echo "exit $?"
cat tapes/gost-20999-format-example.iso.ptp tapes/gost-20999-format-example.iso.ptp > twice.ptp
$TAPE diff twice.ptp twice.ptp; echo "exit $?"
$TAPE restore twice.ptp twice.ptp -o out.ptp --no-doubts-file | tail -1; echo "exit $?"
