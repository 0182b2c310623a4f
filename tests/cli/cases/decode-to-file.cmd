$TAPE decode tapes/16k20f3s5-turning.iso.ptp -o part.txt && cmp part.txt tapes/16k20f3s5-turning.txt && echo identical
