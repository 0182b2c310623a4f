# Dumps by xxd, hexdump -C and od -t x1 (whose '*' stands for repeated lines) read as the tape they show;
# od's default word dump is refused with the advice to dump bytes.
od -t x1 tapes/16k20f3s5-turning.iso.ptp > od.txt && $TAPE decode od.txt | cmp - tapes/16k20f3s5-turning.txt && echo "od -t x1: the program"
hexdump -C tapes/16k20f3s5-turning.iso.ptp > hd.txt && $TAPE decode hd.txt | cmp - tapes/16k20f3s5-turning.txt && echo "hexdump -C: the program"
xxd tapes/16k20f3s5-turning.iso.ptp > x.txt && $TAPE info x.txt | sed -n '2p'
od tapes/16k20f3s5-turning.iso.ptp > words.txt; $TAPE decode words.txt; echo "exit $?"
