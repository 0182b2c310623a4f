# One read with a parity error no single change can settle: the frame stays as read, its candidates
# are listed, the stretch to read again is given in centimetres, and the exit status is 1.
cp tapes/gost-20999-format-example.iso.ptp one.ptp
printf '\x31' | dd of=one.ptp bs=1 seek=120 conv=notrunc status=none
$TAPE restore --json one.ptp -o out.ptp; echo "exit $?"
cmp -l out.ptp one.ptp && echo "written as read"
