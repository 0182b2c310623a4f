// The format modules, one file each; image.cpp lists them.
#pragma once

#include "tape/image.hpp"

namespace tape {

ImageFormat raw_image_format();
ImageFormat holes_image_format();
ImageFormat hex_image_format();
ImageFormat hex8_image_format();
ImageFormat hex5_image_format();

}  // namespace tape
