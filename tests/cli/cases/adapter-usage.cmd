# tape adapter needs an adapter: device string (another backend is a usage error) that answers (a
# file that is no adapter is a device failure, named without a frame: no run had started).
$TAPE adapter info serial:/dev/null
echo "exit $?"
$TAPE adapter selftest 'adapter:/dev/null?tracks=8'
echo "exit $?"
$TAPE adapter
