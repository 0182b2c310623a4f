# A program with as much of Fanuc (an M98 call) as of LinuxCNC (G64 P): the two are close, the text is
# read as the first, and only what both readings find is reported (X twice is wrong in both).
printf 'G21 G64 P0.02\nG0 X0 Y0\nM98 P100\nG1 X1 X2 F100\nM30\n' > close.nc
$TAPE -v lint close.nc; echo "exit $?"
$TAPE lint --json close.nc
