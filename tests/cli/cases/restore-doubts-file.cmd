# A frame left in doubt whose readings all hold parity reads as a good character: the doubts file beside
# the image (IMAGE.restore.json) makes decode and lint of the image say so, and exit 1. Once the image
# is changed, the file is another image's and is not heard.
cp tapes/gost-20999-format-example.iso.ptp a.ptp
cp tapes/gost-20999-format-example.iso.ptp b.ptp
printf '\x59' | dd of=b.ptp bs=1 seek=37 conv=notrunc status=none
$TAPE restore a.ptp b.ptp -o out.ptp >/dev/null; echo "exit $?"
ls out.ptp*
$TAPE decode out.ptp >/dev/null; echo "decode exit $?"
$TAPE lint out.ptp 2>/dev/null | grep doubtful; echo "lint exit $?"
printf '\x00' >> out.ptp
$TAPE decode out.ptp >/dev/null; echo "decode exit $?"
