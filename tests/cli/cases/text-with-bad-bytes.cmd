# A NUL, a control character or a byte that is not UTF-8 in a text program is named with its line and
# column, never punched as blank tape and never taken for a tape image; input bytes are shown escaped.
printf '%%\nN1 G01 X10\nN2 X\0002\nM02\n' > nul.txt
$TAPE encode nul.txt -o nul.ptp; echo "encode: exit $?"
test -e nul.ptp && echo "nul.ptp was written"
$TAPE lint nul.txt; echo "lint: exit $?"
$TAPE blocks nul.txt; echo "blocks: exit $?"
printf '%%\nN1 G01 X10\nN2 (\xd0)\nM02\n' > stray.txt
$TAPE lint stray.txt; echo "lint: exit $?"
$TAPE encode stray.txt -o stray.ptp; echo "encode: exit $?"
printf '%%\nN1 G01 X10\x07\nM02\n' | $TAPE blocks; echo "blocks: exit $?"
printf '%%\nN1 G01\x7f\nM02\n' > del.txt
$TAPE encode del.txt -o del.ptp; echo "encode: exit $?"
printf '\xef\xbb\xbf%%\nN1 G01\n' > bom.txt
$TAPE encode bom.txt -o bom.ptp; echo "encode: exit $?"
