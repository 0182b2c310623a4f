# A hand transcription, one frame a line as eight binary digits, track 8 first (issue 31, moshobo):
# read as the tape it is, an empty line between frames as one blank frame; not a hex dump's offsets.
printf '10001101\n00001010\n11010111\n11000101\n11001100\n11000011\n11001111\n01001101\n11000101\n\n10001101\n00001010\n' > tape.txt
$TAPE info tape.txt; echo "exit $?"
$TAPE decode tape.txt | od -c | sed -n 1,2p
printf '10001101\n0000101\n11010111\n11000101\n' > cut.bits
$TAPE decode cut.bits; echo "exit $?"
