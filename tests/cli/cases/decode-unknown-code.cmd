$TAPE decode tapes/bad/random-noise.ptp
