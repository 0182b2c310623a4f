printf "%%\nN1 G1 X12.5 F100\nN2 M02\n" | $TAPE format --spec "N03 G02 X+053 F031 M02" -o out.ptp && $TAPE decode out.ptp && $TAPE info out.ptp | grep "^code:"
