$TAPE blocks --explain tapes/circle-examples.iso.ptp
