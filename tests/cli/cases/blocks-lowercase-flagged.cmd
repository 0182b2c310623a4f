# Nothing is dropped: lowercase words a ГОСТ reading does not know are listed, flagged, reported once.
printf '%%\nN1 g20 x1.5\nN2 M02\n' | $TAPE blocks --dialect gost
printf '%%\nN1 g20 x1.5\nN2 M02\n' | $TAPE blocks --dialect linuxcnc
