# Fanuc's ';' as manuals print it becomes the end of block on tape; ';' in a comment stays.
printf '%%\nO1000;\nG00 X1 (A;B);\nM30;\n%%\n' > p.nc
$TAPE -v feed --leader 0 --trailer 0 p.nc file:p.ptp && $TAPE decode p.ptp
