printf "%%\nN1 X125\nN2 M02\n" | $TAPE format --spec "DS N03 X+053 M02"
