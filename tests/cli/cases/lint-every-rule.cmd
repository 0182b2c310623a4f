printf "%%\nN5 X1 Y2 X3 G01 G00 F-100\nN3 G17 G18 X Y1.2.3 (A:B) /N4\nN6 x1 #\nN7 M30\nAFTER THE END\n" | $TAPE lint --dialect gost
