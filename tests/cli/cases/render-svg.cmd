# The tape to scale as SVG: valid XML, the same bytes twice, an existing output kept without --force.
$TAPE encode --leader 40 --trailer 5 --label "N1" tapes/circle-examples.txt -o t.ptp
$TAPE render t.ptp -o a.svg && $TAPE render t.ptp -o b.svg && cmp a.svg b.svg && echo "same bytes"
xmllint --noout a.svg && echo "valid"
head -c 300 a.svg; echo
grep -o '<circle' a.svg | wc -l  # feed holes and code holes
$TAPE render t.ptp -o a.svg; echo "exit $?"
