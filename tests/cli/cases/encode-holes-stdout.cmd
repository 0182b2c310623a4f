printf "%%\nN1 M02\n" | $TAPE encode --format holes --leader 1 --trailer 1
