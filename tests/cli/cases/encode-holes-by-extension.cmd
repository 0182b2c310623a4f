$TAPE encode tapes/16k20f3s5-turning.txt -o part.holes && head -4 part.holes && $TAPE decode part.holes | cmp - tapes/16k20f3s5-turning.txt && echo identical
