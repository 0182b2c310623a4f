cat tapes/gost-20999-format-example.eia.ptp | $TAPE decode
