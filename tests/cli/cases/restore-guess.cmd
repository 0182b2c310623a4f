# --guess: one read whose G lost a hole; D90, B90, V90 and F90 read as well as G90 (an N90 inside the
# block breaks the tape's block numbers), so without it nothing is guessed (exit 1, unresolved); with it
# the likeliest is written, marked guessed, with the others listed, and the run still exits 1 with
# "complete": false.
cp tapes/gost-20999-format-example.iso.ptp one.ptp
printf '\x46' | dd of=one.ptp bs=1 seek=107 conv=notrunc status=none
$TAPE restore one.ptp -o plain.ptp --no-doubts-file | grep -A1 "frame 108"; echo "exit $?"
$TAPE restore --guess one.ptp -o guessed.ptp --no-doubts-file | grep -A9 "frame 108"; echo "exit $?"
$TAPE restore --guess --json one.ptp -o guessed2.ptp --no-doubts-file | grep -o '"complete":false\|"guessed":1'
