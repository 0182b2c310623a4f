$TAPE decode tapes/bad/pdp8-bin-loader.bin
