# A label alone: 10 blank frames, the letters, 10 blank frames; shown as holes, then read back by info.
$TAPE label "Hi 7" -o hi.ptp && $TAPE show hi.ptp && $TAPE info hi.ptp | grep -E 'leader label|frames:|leader:|data:'
