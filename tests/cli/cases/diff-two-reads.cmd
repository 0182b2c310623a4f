# Two reads compared after alignment: a flipped hole, a dropped frame, a doubled one.
cp tapes/gost-20999-format-example.iso.ptp a.ptp
head -c 150 tapes/gost-20999-format-example.iso.ptp > b.ptp
tail -c +152 tapes/gost-20999-format-example.iso.ptp >> b.ptp
printf '\x31' | dd of=a.ptp bs=1 seek=120 conv=notrunc status=none
$TAPE diff a.ptp b.ptp; echo "exit $?"
$TAPE diff a.ptp a.ptp; echo "exit $?"
