# In a Fanuc lathe program G90, G92 and G94 are turning cycles (G code system A), not ГОСТ's absolute
# dimensions, position preset and feed per minute; in a mill program G90 is absolute. Until a program
# shows which machine it is for, both meanings are named.
printf '%%\nO1103 (PIN)\nN10 G21 G40 G97 G99\nN30 T0101\nN40 G50 S2000\nN70 G94 X-1.6 Z0.5 F0.2\nN100 G90 X46. Z-60. F0.25\nN220 G92 X23.3 Z-28. F2.\nN300 M30\n%%\n' > pin.nc
$TAPE blocks --explain pin.nc
$TAPE blocks --explain --lang ru pin.nc
printf '%%\nO2000\nG17 G90 G54 G0 X0 Y0\nG1 Z-1 F100\nM30\n%%\n' > plate.nc
$TAPE blocks --explain plate.nc
