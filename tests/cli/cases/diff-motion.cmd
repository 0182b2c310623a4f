# tape diff --motion: the same square written two ways (G90 and G91, lines split, an arc by I/J and in two
# halves by R) is the same toolpath; moved by 0.01 mm it differs at its first piece that moved, with its
# block in each; a rapid where the other feeds differs.
printf '%%\nO0001\nN10 G90 G17 G21 G00 X0 Y0 Z5.\nN20 G01 Z-1. F100.\nN30 X100.\nN40 Y50.\nN50 G02 X100. Y10. I0 J-20.\nN60 G00 Z5.\nN70 M30\n%%\n' >a.nc
printf '%%\nO0002\nN1 G90 G17 G21 G00 X0 Y0 Z5.\nN2 G91 G01 Z-6. F200.\nN3 X40.\nN4 X60.\nN5 Y40.\nN6 Y10.\nN7 G90 G02 X120. Y30. R20.\nN8 X100. Y10. R20.\nN9 G00 Z5.\nN10 M30\n%%\n' >b.nc
$TAPE diff --motion a.nc b.nc; echo "exit $?"
sed 's/N40 Y50./N40 Y50.01/' a.nc >c.nc
$TAPE diff --motion a.nc c.nc; echo "exit $?"
$TAPE diff --motion a.nc c.nc --tolerance 0.02; echo "exit $?"
sed 's/N20 G01 Z-1. F100./N20 G00 Z-1./' a.nc >d.nc
$TAPE diff --motion a.nc d.nc; echo "exit $?"
