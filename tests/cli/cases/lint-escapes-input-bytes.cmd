# A control character read from a tape reaches lint's message escaped, never raw on the terminal.
printf '%%\nN1 G01 X1\nN2 G01 Y\0072\nM02\n' > bel.txt
$TAPE encode bel.txt -o bel.ptp
$TAPE lint bel.ptp; echo "exit $?"
