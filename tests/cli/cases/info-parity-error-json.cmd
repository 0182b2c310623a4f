$TAPE info --json tapes/bad/parity-error.ptp
