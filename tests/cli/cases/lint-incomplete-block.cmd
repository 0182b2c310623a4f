# A tape cut in the middle of a block: warnings, not errors.
printf '%%\nN1 G00 X1\nN2 G01 X2 F100' > cut.txt
$TAPE encode --trailer 0 cut.txt -o cut.ptp
$TAPE lint --dialect gost cut.ptp; echo "exit $?"
