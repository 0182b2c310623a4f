# The backends, then the ports attached: a fake sysfs with a tape adapter, a USB serial adapter and a
# virtual terminal (no device behind it, not listed), as the kernel lays them out.
mk_port() {  # NAME USBDIR INTERFACE VID PID SERIAL MAKER PRODUCT
  mkdir -p "sys/devices/$2/$3/tty/$1" sys/class/tty
  printf '%s\n' "$4" >"sys/devices/$2/idVendor"
  printf '%s\n' "$5" >"sys/devices/$2/idProduct"
  [ -n "$6" ] && printf '%s\n' "$6" >"sys/devices/$2/serial"
  printf '%s\n' "$7" >"sys/devices/$2/manufacturer"
  printf '%s\n' "$8" >"sys/devices/$2/product"
  ln -s "../../../$3" "sys/devices/$2/$3/tty/$1/device"
  ln -s "../../devices/$2/$3/tty/$1" "sys/class/tty/$1"
}
mk_port ttyACM1 pci0/usb1/1-2 1-2:1.0 1209 0001 TP0002 tape "paper tape adapter"
mk_port ttyACM0 pci0/usb1/1-1 1-1:1.0 1209 0001 TP0001 tape "paper tape adapter"
mk_port ttyUSB0 pci0/usb1/1-3 1-3:1.0 0403 6001 "" FTDI "FT232R USB UART"
mkdir -p sys/class/tty/tty0
TAPE_SYSFS_ROOT=$PWD/sys $TAPE devices
echo "--- none attached"
TAPE_SYSFS_ROOT=$PWD/nothing $TAPE devices | sed -n '$p'
