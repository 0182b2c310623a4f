# Inputs no paper tape can be are refused before they are held: a raw file of more than 10^8 frames
# (254 km) by its size. An output format that cannot hold the frames is a message, not an abort. A code
# the reads do not fit is said, and nothing is repaired; --parity given alone means ISO with that parity.
truncate -s 100000001 huge.ptp
$TAPE restore huge.ptp tapes/gost-20999-format-example.iso.ptp -o out.ptp; echo "exit $?"
$TAPE diff huge.ptp tapes/gost-20999-format-example.iso.ptp; echo "exit $?"
$TAPE restore tapes/gost-20999-format-example.iso.ptp -o r.hex5; echo "exit $?"
$TAPE restore --format hex5 tapes/gost-20999-format-example.iso.ptp -o r.out; echo "exit $?"
test -e r.hex5 || test -e r.out || echo "nothing written"
$TAPE restore --code eia tapes/gost-20999-format-example.iso.ptp tapes/gost-20999-format-example.iso.ptp -o e.ptp >/dev/null; echo "exit $?"
$TAPE restore --parity odd tapes/gost-20999-format-example.iso.ptp tapes/gost-20999-format-example.iso.ptp -o o.ptp >/dev/null; echo "exit $?"
