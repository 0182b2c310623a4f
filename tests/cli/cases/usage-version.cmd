$TAPE --version
