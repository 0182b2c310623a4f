$TAPE blocks --json tapes/16k20f3s5-turning.eia.ptp
