# lint with a profile that gives the axes' travel: X 620 and X 10 are 610 mm apart where X travels 500,
# one of them outside wherever G54 puts zero; across a work offset change nothing is certain. Fanuc's
# extended work offsets (G54.1 P1..P300) are codes, not a point the format lacks.
export XDG_CONFIG_HOME=$PWD/config
cat > vmc.toml <<'TOML'
name = "vmc"
title = "test mill"
kind = "mill"
dialect = "fanuc"
source = "a test's own machine"

[format]
spec = "% / DS O04 N04 G03 X+053 Y+053 Z+053 P+080 F053 S05 T08 M03 D03 H03"

[[axis]]
name = "X"
min_mm = 0
max_mm = 500
TOML
printf '%%\nO0001\nG90 G54 G00 X10. Y0\nG01 X300. F200.\nX620.\nG55\nX0\nX450.\nM30\n%%\n' > travel.nc
$TAPE lint --machine ./vmc.toml travel.nc; echo "exit $?"
printf '%%\nO0002\nG90 G54.1 P1 G00 X0 Y0\nG54.1 P48 X10.\nG54.1 P300 X20.\nM30\n%%\n' > offsets.nc
$TAPE lint --machine fanuc-16 offsets.nc; echo "exit $?"
