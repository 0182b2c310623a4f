# A read of noise longer than the tape's two good reads: the code is the one the good reads fit (it was
# taken from the longest read, which turned the run to "no code" and repaired nothing), and the code is
# not said to misfit the reads because the noise fails it.
cp tapes/gost-20999-format-example.iso.ptp r1.ptp
cp tapes/gost-20999-format-example.iso.ptp r2.ptp
LC_ALL=C awk 'BEGIN { srand(5); for (i = 0; i < 3000; i++) printf "%c", int(rand() * 255) + 1 }' >noise.ptp
$TAPE restore --drop-unrelated r1.ptp noise.ptp r2.ptp -o out.ptp --no-doubts-file | head -1; echo "exit $?"
cmp out.ptp tapes/gost-20999-format-example.iso.ptp && echo "restored from the two good reads"
