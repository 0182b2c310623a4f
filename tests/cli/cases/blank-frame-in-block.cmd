# In EIA the one-hole characters (0 1 2 4 8 - and space) become blank tape when their hole is lost:
# Z-1 silently reads Z1. A blank frame inside a block is reported with its frame by decode, lint and
# blocks as a warning, an error (exit 1) with --strict; blank tape between blocks stays silent.
printf '%%\nN1 G01 Z-1 F100\nN2 X8\nN3 M02\n' > part.txt
$TAPE encode --code eia --leader 10 --trailer 10 part.txt -o part.ptp
# frame 21 is the '-' of Z-1 (10 leader frames, then % EOB N 1 SP G 0 1 SP Z): blank it
printf '\000' | dd of=part.ptp bs=1 seek=20 conv=notrunc status=none
$TAPE decode part.ptp; echo "exit $?"
$TAPE decode --strict part.ptp >/dev/null; echo "exit $?"
$TAPE lint part.ptp; echo "exit $?"
$TAPE lint --strict part.ptp; echo "exit $?"
$TAPE blocks part.ptp; echo "exit $?"
$TAPE blocks --strict part.ptp >/dev/null; echo "exit $?"
