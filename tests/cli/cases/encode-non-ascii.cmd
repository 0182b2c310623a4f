$TAPE encode tapes/bad/non-ascii.txt -o out.ptp
