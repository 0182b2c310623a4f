printf "%%\r\nM02\r\n" | $TAPE encode --leader 0 --trailer 0 | od -An -tx1
