# A file: device takes no settings: "file:PATH?key=value" is refused as the backend refuses it, and no
# file named with the '?' is written.
$TAPE punch tapes/16k20f3s5-turning.iso.ptp 'file:copy.ptp?baud=9600'; echo "exit $?"
$TAPE feed tapes/16k20f3s5-turning.txt 'file:copy.ptp?x=1'; echo "exit $?"
$TAPE punch tapes/16k20f3s5-turning.iso.ptp 'file:'; echo "exit $?"
ls
