# Control characters read from a tape reach the listing escaped (\x07, \x1B), as "! not read:" shows
# them, never raw on the terminal: in a word run, in a comment, in the program number.
printf '%%1\033[2J\nN1 G01 X1\nN2 G01 Y\0072 (BELL\007)\nM02\n' > bel.txt
$TAPE encode bel.txt -o bel.ptp
$TAPE blocks bel.ptp; echo "exit $?"
