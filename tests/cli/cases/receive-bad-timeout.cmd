$TAPE receive file:tapes/16k20f3s5-turning.iso.ptp -o in.ptp --timeout nan; echo "exit $?"
$TAPE receive file:tapes/16k20f3s5-turning.iso.ptp -o in.ptp --timeout -1; echo "exit $?"
$TAPE receive file:tapes/16k20f3s5-turning.iso.ptp -o in.ptp --timeout 1e999; status=$?; ls; exit $status
