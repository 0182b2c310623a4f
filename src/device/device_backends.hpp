// The backends' open functions; device.cpp lists them in one table.
#pragma once

#include <memory>
#include <string_view>

#include "adapter_session.hpp"
#include "tape/device.hpp"

namespace tape {

std::unique_ptr<Transport> open_file_device(std::string_view rest, DeviceUse use, bool replace);
std::unique_ptr<Transport> open_serial_device(std::string_view rest, DeviceUse use, bool replace);

// Tape adapters: the device, and the bare packet pipe for asking the adapter about itself.
std::unique_ptr<Transport> open_adapter_device(std::string_view rest, DeviceUse use, bool replace);
std::unique_ptr<adapter::PacketPipe> open_cdc_pipe(std::string_view rest);
std::unique_ptr<Transport> open_usb_device(std::string_view rest, DeviceUse use, bool replace);
std::unique_ptr<adapter::PacketPipe> open_usb_pipe(std::string_view rest);
std::unique_ptr<Transport> open_hid_device(std::string_view rest, DeviceUse use, bool replace);
std::unique_ptr<adapter::PacketPipe> open_hid_pipe(std::string_view rest);

}  // namespace tape
