# Frames 95 to 110 of the sample tape, mirrored, in strips of 25.4 mm (10 frames): two strips.
$TAPE render --from 95 --to 110 --mirror --strip-length 25.4 tapes/16k20f3s5-turning.iso.ptp
