# An input that never ends is refused past 10^8 frames (254 km of tape), in bounded memory; with --to
# only the frames drawn are read.
$TAPE render --format raw /dev/zero -o z.svg; echo "exit $?"
$TAPE render --format raw /dev/zero --to 20 -o z.svg; echo "exit $?"
grep -c '<circle' z.svg
