# A read of another tape among the reads is named by its file; with --drop-unrelated the run goes on
# without it, and says so.
cp tapes/gost-20999-format-example.iso.ptp r1.ptp
cp tapes/gost-20999-format-example.iso.ptp r2.ptp
cp tapes/16k20f3s5-turning.iso.ptp other.ptp
$TAPE restore r1.ptp other.ptp r2.ptp -o out.ptp; echo "exit $?"
$TAPE restore --drop-unrelated r1.ptp other.ptp r2.ptp -o out.ptp --no-doubts-file | head -4; echo "exit $?"
cmp out.ptp tapes/gost-20999-format-example.iso.ptp && echo "restored from the two others"
