// The format modules, one file each; image.cpp lists them.
#pragma once

#include "tape/image.hpp"

namespace tape {

ImageFormat raw_image_format();
ImageFormat holes_image_format();
ImageFormat hex_image_format();
ImageFormat hex8_image_format();
ImageFormat hex5_image_format();
ImageFormat dump_image_format();
ImageFormat bits_image_format();

/// The code a header comment line names: "# code: ita2" or "# code: iso, parity even; ...", as the writers
/// put it; nullopt for another line.
std::optional<Code> header_code(std::string_view comment);

}  // namespace tape
