# An Okuma-style program (named variables, a $NAME% header, N labels): no known dialect fits, so only
# what holds for every control is checked; nothing is wrong with it, so exit 0. -v says why. A
# Cyrillic letter typed for X is wrong on every control and is still found.
printf '$FLANGE.MIN%%\n(OKUMA LATHE)\nPRES=1 (CHUCK PRESSURE)\nFLAN=318\nIF[PRES EQ 1]NM59\nNM59 M59\nN10 G96 G0 X=FLAN+5 Z=2 S300 M3\nG1 X=FLAN-7 F.2\nM02\n' > flange.nc
$TAPE lint flange.nc; echo "exit $?"
$TAPE -v lint flange.nc; echo "exit $?"
sed 's/G1 X=FLAN-7/G1 Х=FLAN-7/' flange.nc > typo.nc
$TAPE lint typo.nc; echo "exit $?"
$TAPE blocks flange.nc >/dev/null; echo "exit $?"
