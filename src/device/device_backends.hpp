// The backends' open functions; device.cpp lists them in one table.
#pragma once

#include <memory>
#include <string_view>

#include "adapter_session.hpp"
#include "tape/device.hpp"

namespace tape {

std::unique_ptr<Transport> open_file_device(std::string_view rest, DeviceUse use, bool replace);
std::unique_ptr<Transport> open_serial_device(std::string_view rest, DeviceUse use, bool replace);

// Tape adapters: each backend opens its packet pipe alone; the table makes the device of it, with the
// session and settings all of them share (adapter::open_transport).
std::unique_ptr<adapter::PacketPipe> open_cdc_pipe(const DeviceQuery& query);
std::unique_ptr<adapter::PacketPipe> open_usb_pipe(const DeviceQuery& query);
std::unique_ptr<adapter::PacketPipe> open_hid_pipe(const DeviceQuery& query);

}  // namespace tape
