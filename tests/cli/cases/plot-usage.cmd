# tape plot: the output's extension says the format; mill views are not for a lathe, lathe options not for
# a mill; nothing to draw is bad data.
printf 'G00 X0 Y0\nG01 X10 F100\nM30\n' >p.nc
$TAPE plot p.nc -o p.jpg; echo "exit $?"
$TAPE plot p.nc --lathe --view xz -o p.svg; echo "exit $?"
$TAPE plot p.nc --front-post -o p.svg; echo "exit $?"
printf 'G00 X0 Y0\nM30\n' >empty.nc
$TAPE plot empty.nc -o e.svg; echo "exit $?"
$TAPE plot p.nc -o p.svg && $TAPE plot p.nc -o p.svg; echo "exit $?"
