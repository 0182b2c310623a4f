$TAPE encode tapes/gost-20999-format-example.txt | $TAPE punch - file:punched.ptp && $TAPE read file:punched.ptp -o read.holes && $TAPE decode read.holes
