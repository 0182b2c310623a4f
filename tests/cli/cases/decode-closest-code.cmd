# Two parity errors in 18 frames: no code fits (one in ten fails). decode says how to get the text; with
# -k it decodes with the closest code, each bad frame marked, and says it is only the closest (issue 31).
printf '\x8d\x0a\xd7\xc5\x4c\xc3\xcf\x4d\xc5\x8d\x0a\xd7\xc5\xcc\x43\xcf\x4d\xc5' > two-bad.ptp
$TAPE decode two-bad.ptp; echo "exit $?"
$TAPE decode -k two-bad.ptp; echo "exit $?"
$TAPE decode -k --code iso two-bad.ptp; echo "exit $?"
