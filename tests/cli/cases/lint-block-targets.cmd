# A lathe cycle's P and Q name the first and last block of its profile: a block that is not there, and
# one whose number stands twice, are found (the shape of cade_O58215.nc); M98 P names a program and is
# not checked.
printf '%%\nO58215\nG71 P45 Q58 U0.01 W0.005 D0.025 F0.01\nN45 G00 X0.0 Z0.0\nN45 G00 X0.0 Z0.0\nG01 X1.8 Z-2.0\nM98 P5001\nM30\n%%\n' > snowman.nc
$TAPE lint snowman.nc; echo "exit $?"
