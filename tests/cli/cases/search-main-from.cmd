printf "%%10\n:1 G90\nN2 X1\n:3 G91\nN4 M02\n" | $TAPE encode -o t.ptp && $TAPE search --main --from 115 t.ptp
