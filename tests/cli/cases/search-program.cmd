printf "%%10\n:1 G90\nN4 M02\n%%020\n:5 X2\nN6 M30\n" > p.txt && $TAPE search --program 20 p.txt
