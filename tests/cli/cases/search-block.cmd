$TAPE search --block 7 tapes/gost-20999-format-example.eia.ptp
