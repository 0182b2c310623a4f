# A file: device gets an image in the format of its extension (or --format), written at once.
$TAPE punch tapes/gost-20999-format-example.iso.ptp file:copy.holes && sed -n 1,6p copy.holes &&
  $TAPE punch copy.holes file:copy.ptp && cmp copy.ptp tapes/gost-20999-format-example.iso.ptp && echo same frames
