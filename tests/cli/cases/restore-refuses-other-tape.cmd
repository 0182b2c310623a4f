# Reads of two different tapes are refused, and nothing is written.
$TAPE restore tapes/gost-20999-format-example.iso.ptp tapes/16k20f3s5-turning.iso.ptp -o out.ptp; echo "exit $?"
test -e out.ptp || echo "no output"
