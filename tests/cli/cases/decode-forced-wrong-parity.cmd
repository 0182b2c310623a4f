# A parity given by hand that the tape does not have: the tape reads cleanly as ISO, and that is said.
$TAPE decode --parity mark tapes/gost-20999-format-example.iso.ptp; echo "exit $?"
$TAPE decode --code iso tapes/16k20f3s5-turning.eia.ptp; echo "exit $?"
$TAPE info --code eia tapes/gost-20999-format-example.iso.ptp | grep -E "^(code|note):"
