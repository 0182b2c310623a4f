$TAPE decode no-such-tape.ptp
