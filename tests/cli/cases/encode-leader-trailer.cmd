printf "%%\nM02\n" | $TAPE encode --leader 2 --trailer 1 | od -An -tx1
