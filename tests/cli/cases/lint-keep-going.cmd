# A damaged tape: without -k lint stops at the first bad frame; with it, bad frames are findings
# among the others and the rest of the tape is checked (exit 1).
$TAPE lint tapes/bad/parity-error.ptp; echo "exit $?"
$TAPE lint -k tapes/bad/parity-error.ptp; echo "exit $?"
