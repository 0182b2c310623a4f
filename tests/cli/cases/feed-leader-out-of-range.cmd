$TAPE feed --leader -1 tapes/16k20f3s5-turning.txt file:fed.ptp; echo "exit $?"
$TAPE feed --trailer -1 tapes/16k20f3s5-turning.txt file:fed.ptp; echo "exit $?"
$TAPE feed --leader 18446744073709551615 tapes/16k20f3s5-turning.txt file:fed.ptp; echo "exit $?"
$TAPE feed --trailer 100001 tapes/16k20f3s5-turning.iso.ptp file:fed.ptp; status=$?; ls; exit $status
