# A block found by search is shown with its control characters escaped, never raw on the terminal.
printf '%%\nN1 G01 X1\nN2 G01 Y\0072 (BELL\007)\nM02\n' > bel.txt
$TAPE encode bel.txt -o bel.ptp
$TAPE search --block 2 bel.ptp; echo "exit $?"
