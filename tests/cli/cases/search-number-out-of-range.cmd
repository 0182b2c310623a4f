# Block numbers and frames out of range are usage errors with the range, not wrapped-round numbers.
$TAPE search --main -5 tapes/gost-20999-format-example.txt; echo "exit $?"
$TAPE search --block 99999999999999999999 tapes/gost-20999-format-example.txt; echo "exit $?"
$TAPE search --block -1 tapes/gost-20999-format-example.txt; echo "exit $?"
$TAPE search --block 5 --from 0 tapes/gost-20999-format-example.txt; echo "exit $?"
$TAPE search --main tapes/gost-20999-format-example.txt | sed -n 1p; echo "exit $?"
