printf "%%10\n:1 G90\nN2 X1\n:3 G91\nN4 M02\n%%20\n:5 X2\nN6 M30\n" | $TAPE encode | $TAPE search --main 5
