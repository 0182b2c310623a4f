# tape feed --from-block --show after the modal state goes to where the block starts (issue 32): O0007's
# N70 arc starts at X50 Y10 Z-5: up to Z50 (the highest the program rapids to), across, down at F100.
# In G91 the approach is absolute and G91 comes back; where the tool's place is not known, refused.
printf '%%\nO0007\nN10 G90 G54 G17 G00 X0 Y0 Z50.\nN20 T1 M06\nN30 S1000 M03\nN40 G00 X10. Y10. Z2.\nN50 G01 Z-5. F100.\nN60 G01 X50. Y10.\nN70 G02 X70. Y30. I0 J20.\nN80 G01 Y60.\nN90 G00 Z50.\nN100 M30\n%%\n' > rs.nc
$TAPE feed --from-block N70 --show rs.nc; echo "exit $?"
printf '%%\nO0008\nN10 G21 G90 G00 X0 Y0 Z20.\nN20 G91 G01 Z-22. F50.\nN30 X10.\nN40 Y5.\nN50 M30\n%%\n' > inc.nc
$TAPE feed --from-block N40 --show inc.nc; echo "exit $?"
printf '%%\nO0009\nN10 G90 G00 X0 Y0\nN20 G01 X5. F100.\nN30 X10.\nN40 M30\n%%\n' > noz.nc
$TAPE feed --from-block N30 --show noz.nc; echo "exit $?"
printf '%%\nO0010\nN10 G21 G18 G00 X50. Z5.\nN20 G01 X20. F0.2\nN30 Z-30.\nN40 X40.\nN50 M30\n%%\n' > lathe.nc
$TAPE feed --from-block N40 --show lathe.nc; echo "exit $?"
$TAPE feed --from-block N40 --lathe --show lathe.nc; echo "exit $?"
