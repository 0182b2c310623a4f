printf "PART 7-114\n%%41\nN1 G00 X1 (START)\n/N2 M00\nN3 M30\nNOTES\n" | $TAPE blocks
