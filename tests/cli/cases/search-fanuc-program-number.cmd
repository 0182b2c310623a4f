# Fanuc O numbers are program numbers: --program 12 finds O0012; the '%' after the last program is
# where a rewinding reader stops.
printf '%%\nO0011\nG00 X0\nM30\nO0012\nG00 X1\nM99\n%%\n' > two.nc
$TAPE search --program 12 two.nc
$TAPE search --rewind --from 9 two.nc
