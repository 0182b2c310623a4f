# One file, one tape: feed punches what encode punches, a final '%' without its LF included; --percent
# puts a '%' after a last line without LF on a line of its own.
printf '%%\nO1\nG0 X1\nM30\n%%' > ends-with-percent.nc
$TAPE encode ends-with-percent.nc -o e.ptp
$TAPE feed ends-with-percent.nc file:f.ptp
cmp e.ptp f.ptp && echo "one tape"
printf 'O1\nG0 X1\nM30' > no-percent.nc
$TAPE feed --percent --leader 0 --trailer 0 no-percent.nc file:p.ptp
$TAPE decode p.ptp
