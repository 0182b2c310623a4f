$TAPE lint tapes/circle-examples.txt
