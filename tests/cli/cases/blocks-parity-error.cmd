$TAPE blocks tapes/bad/parity-error.ptp
