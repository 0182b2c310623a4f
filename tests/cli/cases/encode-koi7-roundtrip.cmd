$TAPE encode --charset koi7 tapes/bad/non-ascii.txt -o out.ptp && $TAPE decode --charset koi7 out.ptp
