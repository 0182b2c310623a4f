# Text before the first '%' is leader in every dialect: a comment or a part name is the label, and the
# program after the '%' is read and checked (its X twice is an error).
printf '(POSTED BY CAM)\n%%\nO1234\nG01 X1. X2. F100\nM30\n%%\n' > pre.nc
$TAPE lint pre.nc; echo "exit $?"
printf 'PART 17 REV B\n%%\nO1234 (BRACKET)\nN10 G90 G54 G00 X0 Y0\nN20 G01 X10. Y5. F100.\nN40 M30\n%%\n' > label.nc
$TAPE blocks --dialect fanuc label.nc
