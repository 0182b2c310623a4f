# Through an adapter the control's own lines start, stop and rewind the reader, and the frame rate is the
# adapter's wiring: the serial line's options are refused before anything is opened; so is a wiring that
# cannot work, or puts two lines on one pin.
$TAPE emulate tapes/16k20f3s5-turning.iso.ptp adapter:/dev/no-such-adapter --rate 1000; echo "exit $?"
$TAPE emulate tapes/16k20f3s5-turning.iso.ptp usb:1209:0001 --search-char ';'; echo "exit $?"
$TAPE adapter config adapter:/dev/no-such-adapter --setup 600; echo "exit $?"
$TAPE adapter config adapter:/dev/no-such-adapter --run-pin 3; echo "exit $?"
$TAPE adapter config adapter:/dev/no-such-adapter --data-pins 0,1,2 --tracks 8; echo "exit $?"
$TAPE adapter config adapter:/dev/no-such-adapter --braking 3; echo "exit $?"
