# tape feed --from-block --show prints the restart's header: the program's start, the modal state at
# the block rebuilt as blocks; a restart that cannot be rebuilt is refused, saying why (exit 2).
printf '%%\nO1000 (POCKET)\nN10 G21 G17 G90 G54\nN20 T3 M06\nN30 S2500 M03 M08\nN40 G43 H3 G00 X0 Y0 Z5.\nN50 G01 Z-2. F120.\nN60 X20.\nN70 M30\n%%\n' > pocket.nc
$TAPE feed --from-block N60 --show pocket.nc; echo "exit $?"
printf '%%\nO1\n#1=0\nWHILE [#1 LT 3] DO1\nN60 G01 X#1 F100.\n#1=#1+1\nEND1\nM30\n%%\n' > loop.nc
$TAPE feed --from-block N60 --show loop.nc; echo "exit $?"
$TAPE feed --from-block N60 pocket.nc file:restart.ptp -q; echo "exit $?"
$TAPE decode restart.ptp; echo "exit $?"
$TAPE feed --show pocket.nc; echo "exit $?"
