# A DOS Ctrl-Z after the last line ends the text: not punched, said in a note; info calls the file a
# text program, not an ASCII tape with space parity.
printf '%%\r\nO0097\r\nN10 G00 X1\r\nM30\r\n%%\r\n\032' > p.nc
$TAPE encode --leader 0 --trailer 0 p.nc -o p.ptp && $TAPE decode p.ptp | od -An -c | sed -n '$p'
$TAPE info p.nc | sed -n '4p'
