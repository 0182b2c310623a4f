# A negative or huge --leader/--trailer is a usage error naming the range; nothing is written.
for v in -1 -100 18446744073709551615 9223372036854775807 100001; do
  $TAPE encode tapes/16k20f3s5-turning.txt --leader "$v" -o out.ptp; echo "leader $v: exit $?"
  $TAPE encode tapes/16k20f3s5-turning.txt --trailer "$v" -o out.ptp; echo "trailer $v: exit $?"
done
test -e out.ptp && echo "out.ptp was written"
$TAPE encode tapes/16k20f3s5-turning.txt --leader 100000 --trailer 0 -o out.ptp && wc -c < out.ptp
