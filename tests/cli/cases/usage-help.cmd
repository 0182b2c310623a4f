$TAPE --help | sed -n 1,3p; $TAPE decode --help | grep -c -- --keep-going
