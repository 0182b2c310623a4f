$TAPE info tapes/bad/mark-parity-ascii.ptp | head -6; $TAPE decode --parity mark tapes/bad/mark-parity-ascii.ptp; echo "exit $?"
