$TAPE search --main tapes/gost-20999-format-example.iso.ptp
