# A text program given where a tape image is expected: raw by --format, or by a tape extension.
$TAPE decode --format raw tapes/16k20f3s5-turning.txt; echo "exit $?"
cp tapes/16k20f3s5-turning.txt prog.ptp
$TAPE decode prog.ptp; echo "exit $?"
$TAPE info prog.ptp | head -5
