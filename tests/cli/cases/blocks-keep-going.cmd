# A damaged tape listed past its bad frame: the frame is reported once, the block keeps what was read.
$TAPE blocks -k tapes/bad/parity-error.ptp; echo "exit $?"
$TAPE search -k --block 3 tapes/bad/parity-error.ptp; echo "exit $?"
