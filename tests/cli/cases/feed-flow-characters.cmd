# XON and XOFF must differ (bit 8 is not compared) and be bytes; the file is not created.
$TAPE feed tapes/16k20f3s5-turning.txt file:fed.ptp --xon 0x13 --xoff 0x13; echo "exit $?"
$TAPE feed tapes/16k20f3s5-turning.txt file:fed.ptp --xon 0x11 --xoff 0x91; echo "exit $?"
$TAPE feed tapes/16k20f3s5-turning.txt file:fed.ptp --xon 300; status=$?; ls; exit $status
