$TAPE decode tapes/bad/mark-parity-ascii.ptp
