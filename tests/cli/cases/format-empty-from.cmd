# --from given but empty is an error too, not the same as leaving --from out.
$TAPE format --spec "N03 G02 X+053 Y+053 Z+053 F031 S04 T04 M02" --from "  " tapes/gost-20999-format-example.txt
