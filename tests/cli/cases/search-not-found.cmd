$TAPE search --main 9 tapes/gost-20999-format-example.iso.ptp
