# tape blocks --stats: per tool the least and most of each axis, cutting and rapid length and time. T1
# feeds 100 mm at 200 mm/min (0.5 min); T2 a half circle of radius 10 (31.416 mm) at 100 mm/min.
printf '%%\nO0001\nN10 G90 G17 G21 G00 X0 Y0 Z50.\nN20 T1 M06\nN30 G00 Z0\nN40 G01 X100. F200.\nN50 G00 Z50.\nN60 T2 M06\nN70 G00 X0 Y0 Z0\nN80 G02 X20. Y0 I10. J0 F100.\nN90 G00 Z50.\nN100 M30\n%%\n' >s.nc
$TAPE blocks --stats s.nc --rapid 10000; echo "exit $?"
$TAPE blocks --stats --json s.nc; echo "exit $?"
