# A file has no modem lines and sends no DC1: RTS/CTS and --wait-xon are refused, nothing written.
$TAPE feed tapes/16k20f3s5-turning.txt file:fed.ptp --flow rtscts; echo "exit $?"
$TAPE feed tapes/16k20f3s5-turning.txt file:fed.ptp --wait-xon; status=$?; ls; exit $status
