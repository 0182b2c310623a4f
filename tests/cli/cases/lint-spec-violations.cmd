$TAPE lint --spec "N03 G02 X+053 Y+053 F031 S04 T04 M02" tapes/gost-20999-format-example.txt
