# Cyrillic in the EIA layout (rail on track 1, parity on 5); А after a marker with its top row punched.
$TAPE label --code eia "ДА" -f holes && $TAPE label --code eia "ДА" -o da.ptp && $TAPE info --json da.ptp | grep -o '"leader_label": {[^}]*}'
# show draws the label's holes; they are letters, not bad frames (exit 0); render shades none of them.
$TAPE show da.ptp >/dev/null; echo "show exit $?"
$TAPE render da.ptp | grep -o 'class="mark' | wc -l
