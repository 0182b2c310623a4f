# Checked before the device is opened: a file: device is not created.
$TAPE emulate tapes/16k20f3s5-turning.iso.ptp file:out.ptp --rate 0; echo "exit $?"
$TAPE emulate tapes/16k20f3s5-turning.iso.ptp file:out.ptp --rate 1e-300; echo "exit $?"
$TAPE emulate tapes/16k20f3s5-turning.iso.ptp file:out.ptp --rate nan; echo "exit $?"
$TAPE emulate tapes/16k20f3s5-turning.iso.ptp file:out.ptp --search-char % ; echo "exit $?"
$TAPE emulate tapes/16k20f3s5-turning.iso.ptp file:out.ptp --rewind-char 0x13; status=$?; ls; exit $status
