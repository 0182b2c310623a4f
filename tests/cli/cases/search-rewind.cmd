printf "%%10\n:1 G90\nN4 M02\n%%20\n:5 X2\nN6 M30\n" | $TAPE encode -o t.ptp && $TAPE search --rewind --from 130 t.ptp
