$TAPE feed tapes/16k20f3s5-turning.txt "serial:/dev/no-such-port?baud=9600"
