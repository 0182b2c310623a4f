# --from applies to every search: blocks and programs before it are not found.
printf 'N10 G00 X0\nN50 G01 X1 F100\nN20 G00 X2\nN50 G01 X3\nM2\n' > p.ngc
$TAPE search --block 50 --from 3 p.ngc
