$TAPE decode tapes/gost-20999-format-example.iso.holes
