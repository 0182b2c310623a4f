# The backends, then the ports attached: a fake sysfs, as the kernel lays it out, with two tape adapters
# on CDC, a USB serial adapter, a virtual terminal (no device behind it, not listed), and an adapter
# offering its vendor bulk and HID interfaces besides CDC (listed once for each). Another maker's vendor
# interface and a keyboard's hidraw node are not tape adapters and not listed.
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
mk_usb() {  # USBDIR VID PID SERIAL MAKER PRODUCT
  mkdir -p "sys/devices/$1"
  printf '%s\n' "$2" >"sys/devices/$1/idVendor"
  printf '%s\n' "$3" >"sys/devices/$1/idProduct"
  [ -n "$4" ] && printf '%s\n' "$4" >"sys/devices/$1/serial"
  printf '%s\n' "$5" >"sys/devices/$1/manufacturer"
  printf '%s\n' "$6" >"sys/devices/$1/product"
  mkdir -p sys/bus/usb/devices
  ln -s "../../../devices/$1" "sys/bus/usb/devices/${1##*/}"
}
mk_interface() {  # USBDIR INTERFACE CLASS
  mkdir -p "sys/devices/$1/$2"
  printf '%s\n' "$3" >"sys/devices/$1/$2/bInterfaceClass"
  mkdir -p sys/bus/usb/devices
  ln -s "../../../devices/$1/$2" "sys/bus/usb/devices/$2"
}
mk_hidraw() {  # NAME USBDIR INTERFACE HIDDEVICE
  mk_interface "$2" "$3" 03
  mkdir -p "sys/devices/$2/$3/$4/hidraw/$1" sys/class/hidraw
  ln -s "../../../$4" "sys/devices/$2/$3/$4/hidraw/$1/device"
  ln -s "../../devices/$2/$3/$4/hidraw/$1" "sys/class/hidraw/$1"
}
mk_port ttyACM2 pci0/usb1/1-4 1-4:1.0 1209 0001 TP0004 tape "paper tape adapter"
mk_interface pci0/usb1/1-4 1-4:1.1 ff
mk_hidraw hidraw1 pci0/usb1/1-4 1-4:1.2 0003:1209:0001.0003
mk_usb pci0/usb1/1-5 046d c31c "" Logitech "USB Keyboard"
mk_hidraw hidraw0 pci0/usb1/1-5 1-5:1.0 0003:046D:C31C.0001
mk_usb pci0/usb1/1-6 0bda 8153 000001 Realtek "USB 10/100/1000 LAN"
mk_interface pci0/usb1/1-6 1-6:1.0 ff
TAPE_SYSFS_ROOT=$PWD/sys $TAPE devices
echo "--- none attached"
TAPE_SYSFS_ROOT=$PWD/nothing $TAPE devices | sed -n '$p'
