# A 5-track tape is told as such, read as ISO by hand or detected.
$TAPE decode --code iso tapes/bad/ita2-5-track.ptp; echo "exit $?"
$TAPE decode tapes/bad/ita2-5-track.ptp; echo "exit $?"
