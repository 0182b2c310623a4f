# The most common file shape in the world: %, program, M30, %. No program-start, no program-end.
printf '%%\nO0100\nG21 G90 G17\nG00 X0 Y0\nG01 X10. F200.\nM30\n%%\n' > part.nc
$TAPE lint part.nc; echo "exit $?"
$TAPE blocks part.nc
