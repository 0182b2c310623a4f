$TAPE info tapes/bad/pdp8-bin-loader.bin && $TAPE info --json tapes/bad/pdp8-bin-loader.bin
