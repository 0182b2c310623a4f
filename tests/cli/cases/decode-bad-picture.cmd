$TAPE decode tapes/bad/bad-picture.holes
