$TAPE feed tapes/16k20f3s5-turning.txt tty:/dev/ttyS0
