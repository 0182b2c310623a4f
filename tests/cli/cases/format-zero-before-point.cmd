# X+05 has no digit before the point and five after (ГОСТ 20999-83 §9.2): with DS the point comes
# first, and lint with the same spec accepts what format wrote.
printf '%%\nN1 G1 X.00012\nN2 X-0.5\nN3 X0\nN4 M02\n' >in.txt
$TAPE format --spec "DS N03 G02 X+05 M02" in.txt -o out.txt || exit
cat out.txt
$TAPE lint --spec "DS N03 G02 X+05 M02" out.txt
