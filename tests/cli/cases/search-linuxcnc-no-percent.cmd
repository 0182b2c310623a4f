# A program without '%' (LinuxCNC, most CAM output) is a program: its blocks are found.
printf 'g21 g90\nN40 g0 x0 y0\nN50 g1 x10 f100\nm2\n' > part.ngc
$TAPE search --block 50 part.ngc
$TAPE lint part.ngc; echo "exit $?"
