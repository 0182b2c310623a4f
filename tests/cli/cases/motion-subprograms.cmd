# Subprograms followed: O0001 calls O1000 (a 10 mm square in G91) twice with L2, as a text and from a tape
# image; the same toolpath as the program written out flat. A call to a program not in the text is named
# at its block, and the comparison cannot tell past it.
printf '%%\nO0001\nN10 G90 G17 G21 G00 X0 Y0 Z5.\nN20 G01 Z-1. F100.\nN30 M98 P1000 L2\nN40 G90 G00 Z5.\nN50 M30\nO1000\nN1 G91 G01 X10.\nN2 Y10.\nN3 X-10.\nN4 Y-10.\nN5 M99\n%%\n' >sub.nc
printf '%%\nO0002\nN10 G90 G17 G21 G00 X0 Y0 Z5.\nN20 G01 Z-1. F100.\nN30 X10.\nN40 Y10.\nN50 X0\nN60 Y0\nN70 X10.\nN80 Y10.\nN90 X0\nN100 Y0\nN110 G00 Z5.\nN120 M30\n%%\n' >flat.nc
$TAPE diff --motion sub.nc flat.nc; echo "exit $?"
$TAPE encode sub.nc -o sub.ptp && $TAPE diff --motion sub.ptp flat.nc; echo "exit $?"
$TAPE blocks --stats sub.nc; echo "exit $?"
sed 's/P1000/P5001/' sub.nc >missing.nc
$TAPE diff --motion missing.nc flat.nc; echo "exit $?"
