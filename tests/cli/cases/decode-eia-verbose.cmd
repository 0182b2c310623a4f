$TAPE -v decode tapes/16k20f3s5-turning.eia.ptp
