$TAPE show tapes/bad/parity-error.ptp | sed -n "135,139p"
