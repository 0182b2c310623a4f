# A tape in no character code (DEC binary loader) is merged by alignment and vote alone.
D="$(dirname "$TAPE")/tape-damage"
for s in 7 8 9; do "$D" tapes/bad/pdp8-bin-loader.bin -f raw -o r$s.bin --seed $s --flips 0.01; done
$TAPE restore --code none -f raw r7.bin r8.bin r9.bin -o out.bin | grep -v "^      "; echo "exit $?"
cmp out.bin tapes/bad/pdp8-bin-loader.bin && echo "restored byte for byte"
