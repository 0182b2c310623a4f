$TAPE --help | head -3; $TAPE decode --help | grep -c -- --keep-going
