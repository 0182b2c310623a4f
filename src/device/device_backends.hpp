// The backends' open functions; device.cpp lists them in one table.
#pragma once

#include <memory>
#include <string_view>

#include "tape/device.hpp"

namespace tape {

std::unique_ptr<Transport> open_file_device(std::string_view rest, DeviceUse use, bool replace);
std::unique_ptr<Transport> open_serial_device(std::string_view rest, DeviceUse use, bool replace);
std::unique_ptr<Transport> open_adapter_device(std::string_view rest, DeviceUse use, bool replace);

}  // namespace tape
