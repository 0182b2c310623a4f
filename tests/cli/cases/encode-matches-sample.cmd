$TAPE encode tapes/gost-20999-format-example.txt -o part.ptp && cmp part.ptp tapes/gost-20999-format-example.iso.ptp && echo identical
