# A character the font does not have, and a label longer than 80 characters: usage errors, nothing written.
$TAPE label "ÄB" -o x.ptp; echo "exit $?"; $TAPE label "$(printf 'A%.0s' $(seq 81))" -o x.ptp; echo "exit $?"; ls
