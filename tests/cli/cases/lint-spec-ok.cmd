$TAPE lint --spec "% : / DS N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02*" tapes/gost-20999-format-example.iso.ptp
