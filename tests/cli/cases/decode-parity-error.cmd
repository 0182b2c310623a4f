$TAPE decode tapes/bad/parity-error.ptp
