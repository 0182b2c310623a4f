$TAPE blocks tapes/16k20f3s5-turning.txt
