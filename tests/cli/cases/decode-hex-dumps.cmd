# Dumps by xxd, hexdump -C and od -t x1 (whose '*' stands for repeated lines) read as the tape they show;
# od's default word dump is refused with the advice to dump bytes.
od -t x1 tapes/16k20f3s5-turning.iso.ptp > od.txt && $TAPE decode od.txt | cmp - tapes/16k20f3s5-turning.txt && echo "od -t x1: the program"
hexdump -C tapes/16k20f3s5-turning.iso.ptp > hd.txt && $TAPE decode hd.txt | cmp - tapes/16k20f3s5-turning.txt && echo "hexdump -C: the program"
xxd tapes/16k20f3s5-turning.iso.ptp > x.txt && $TAPE info x.txt | sed -n '2p'
od tapes/16k20f3s5-turning.iso.ptp > words.txt; $TAPE decode words.txt; echo "exit $?"
# A '*' whose next offset is past any tape's length is refused before the repeats are made (the fuzzer
# found 1 GB asked for by a 3-line dump).
printf '00000000  00 00 00 00 00 00 00 00  00 00 00 00 00 00 00 00  |................|\n*\n400f0020  a5 0a 47 30  |..G0|\n' > far.txt
$TAPE decode far.txt; echo "exit $?"
