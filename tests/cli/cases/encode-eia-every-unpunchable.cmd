# EIA cannot punch '@', '!' or '#': each is named with its line and column, not only the first; past ten,
# the rest are counted.
printf 'O1\nG0 X1 @ Y!\nM30\n(A#B)\n%%\n' > p.nc
$TAPE encode --code eia p.nc -o p.ptp; echo "exit $?"
test -e p.ptp || echo "nothing written"
printf '@@@@@@@@@@@@@@\n' > many.nc
$TAPE encode --code eia many.nc -o m.ptp; echo "exit $?"
