$TAPE encode --code eia tapes/16k20f3s5-turning.txt -o part.ptp && cmp part.ptp tapes/16k20f3s5-turning.eia.ptp && echo identical
