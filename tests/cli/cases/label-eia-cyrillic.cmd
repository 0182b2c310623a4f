# Cyrillic in the EIA layout (rail on track 1, parity on 5); А after a marker with its top row punched.
$TAPE label --code eia "ДА" -f holes && $TAPE label --code eia "ДА" -o da.ptp && $TAPE info --json da.ptp | grep -o '"leader_label": {[^}]*}'
