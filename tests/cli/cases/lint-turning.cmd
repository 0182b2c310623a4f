$TAPE lint tapes/16k20f3s5-turning.iso.ptp
