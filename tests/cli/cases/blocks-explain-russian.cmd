$TAPE blocks --explain --lang ru tapes/gost-20999-format-example.txt
