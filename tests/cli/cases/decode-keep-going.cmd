$TAPE decode --keep-going tapes/bad/parity-error.ptp
