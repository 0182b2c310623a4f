$TAPE search --main --rewind tapes/gost-20999-format-example.iso.ptp
