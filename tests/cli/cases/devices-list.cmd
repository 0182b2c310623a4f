$TAPE devices
