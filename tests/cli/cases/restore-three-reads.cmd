# Three damaged reads of one tape (tape-damage, fixed seeds) restored: the program comes back exactly.
# (Blank leader and trailer follow the median read: two of these reads have one trailer frame more, so
# the image has too; tape diff says it is no difference of the tape.)
D="$(dirname "$TAPE")/tape-damage"
for s in 11 12 13; do "$D" tapes/gost-20999-format-example.iso.ptp -o r$s.ptp --seed $s --damage 0.02; done
$TAPE restore r11.ptp r12.ptp r13.ptp -o out.ptp; echo "exit $?"
$TAPE decode out.ptp | cmp - tapes/gost-20999-format-example.txt && echo "the program restored exactly"
$TAPE diff out.ptp tapes/gost-20999-format-example.iso.ptp; echo "diff exit $?"
