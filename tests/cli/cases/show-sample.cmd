$TAPE show tapes/gost-20999-format-example.eia.ptp | sed -n "1,2p;100,106p"
