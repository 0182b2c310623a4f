$TAPE read file:tapes/16k20f3s5-turning.iso.ptp -o in.ptp --timeout -1; echo "exit $?"
$TAPE read file:tapes/16k20f3s5-turning.iso.ptp -o in.ptp --timeout 86401; status=$?; ls; exit $status
