$TAPE search tapes/gost-20999-format-example.iso.ptp
