# Three damaged reads of one tape (tape-damage, fixed seeds) restored: the program comes back exactly.
# (The length of blank leader and trailer is voted like any other run of equal frames, where a frame
# dropped and one read twice look the same; the punched part is what must be exact.)
D="$(dirname "$TAPE")/tape-damage"
for s in 11 12 13; do "$D" tapes/gost-20999-format-example.iso.ptp -o r$s.ptp --seed $s --damage 0.02; done
$TAPE restore r11.ptp r12.ptp r13.ptp -o out.ptp; echo "exit $?"
$TAPE decode out.ptp | cmp - tapes/gost-20999-format-example.txt && echo "the program restored exactly"
