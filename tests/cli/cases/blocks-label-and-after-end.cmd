printf "PART 7-114 REV B\n%%%%41\nN1 G00 X1 (START)\nN2 M30\nNOTES AFTER THE END\n%%42\n:1 M02\n" | $TAPE blocks --json
