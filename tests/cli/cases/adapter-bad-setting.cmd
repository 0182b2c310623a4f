# An adapter setting out of range is a usage error, said before the adapter is looked for (there is
# none at this path) and before the output is created; so is a direction for a punch.
$TAPE read "adapter:/nonexistent/ttyACM9?tracks=9" -o out.ptp; echo "exit $?"
$TAPE read "usb:1209:0001?sprocket-timeout=0" -o out.ptp; echo "exit $?"
printf "%%\n" > in.ptp
$TAPE punch in.ptp "hid:1209:0001?direction=reverse"; echo "exit $?"
ls
