$TAPE punch tapes/16k20f3s5-turning.iso.ptp file:copy.ptp --rate 0; echo "exit $?"
$TAPE punch tapes/16k20f3s5-turning.iso.ptp file:copy.ptp --rate -5; status=$?; ls; exit $status
