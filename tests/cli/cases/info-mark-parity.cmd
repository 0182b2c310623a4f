$TAPE info tapes/bad/mark-parity-ascii.ptp
