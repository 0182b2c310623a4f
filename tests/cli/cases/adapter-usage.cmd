# tape adapter needs an adapter: device string (another backend is a usage error) that answers (a
# file that is no adapter is a device failure, named without a frame: no run had started).
$TAPE adapter info serial:/dev/null
echo "exit $?"
$TAPE adapter selftest 'adapter:/dev/null?tracks=8'
echo "exit $?"
$TAPE adapter
# tape adapter config: every value is checked before the device is opened (exit 2, nothing sent).
$TAPE adapter config adapter:/dev/null --tracks 9
echo "exit $?"
$TAPE adapter config adapter:/dev/null --invert 0x100
echo "exit $?"
$TAPE adapter config adapter:/dev/null --sample-delay 5001
echo "exit $?"
$TAPE adapter config adapter:/dev/null --strobe both
echo "exit $?"
$TAPE adapter config adapter:/dev/null --watchdog -1
echo "exit $?"
$TAPE adapter config adapter:/dev/null --invert 0x0F
echo "exit $?"
