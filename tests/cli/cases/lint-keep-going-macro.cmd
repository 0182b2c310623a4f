# A bad frame inside a macro expression read past with -k: the bad frame is the block's one finding
# and the JSON stays valid UTF-8.
printf '%%\nO1\n#8=FIX[ABS[#7]]+ATAN[1]/[1]\nM30\n%%\n' > m.nc
$TAPE encode --leader 2 --trailer 2 m.nc -o m.ptp
# flip track 4 of the 'F' of FIX (frame 11: 0xC6 becomes 0xCE, a parity error)
printf '\xce' | dd of=m.ptp bs=1 seek=10 conv=notrunc status=none
$TAPE lint -k --json m.ptp; echo "exit $?"
