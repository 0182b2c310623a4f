printf "%%\nN1 G1 X12.5 Y-3 F100\nN2 M02\n" | $TAPE format --strip-zeros --spaces --spec "N03 G02 X+053 Y+053 F031 M02"
