$TAPE decode tapes/bad/eia-not-in-code.ptp
