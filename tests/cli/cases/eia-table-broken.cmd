printf "LF 8\nA 1,6\n" > broken.tab && $TAPE decode --eia-table broken.tab --code eia tapes/16k20f3s5-turning.eia.ptp
