$TAPE decode --parity mark tapes/bad/mark-parity-ascii.ptp
