$TAPE decode --code eia --parity mark tapes/16k20f3s5-turning.eia.ptp
