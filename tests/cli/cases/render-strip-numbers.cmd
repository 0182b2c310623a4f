# Strips of 300 mm hold 118 frames: the second strip starts at frame 119, and 120 is not written over it.
$TAPE encode --leader 10 --trailer 10 tapes/circle-examples.txt -o t.ptp
$TAPE render t.ptp --strip-length 300 -o t.svg
grep -o '>11[89]<\|>12[0-9]<\|>130<' t.svg | tr '\n' ' '; echo
