$TAPE format --spaces --spec "% : / DS N03 G02 X+053 Z+053 F05 S02 T03 M03" --from "N03 G02 X+052 Z+052 F05 S02 T03 M03" tapes/16k20f3s5-turning.eia.ptp
