printf "HI\n" | $TAPE encode --parity mark --leader 0 --trailer 0 | od -An -tx1
