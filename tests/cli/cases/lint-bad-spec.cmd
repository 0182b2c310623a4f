$TAPE lint --spec "N03 X+1234" tapes/gost-20999-format-example.txt
