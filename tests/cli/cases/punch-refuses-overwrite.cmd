echo keep > copy.ptp
$TAPE punch tapes/16k20f3s5-turning.iso.ptp file:copy.ptp; status=$?; cat copy.ptp; ls; exit $status
