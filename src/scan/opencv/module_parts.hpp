// The picture module's functions (picture_module.hpp), one file a concern: module_codecs.cpp,
// module_blobs.cpp; module.cpp puts them in the table.
#pragma once

#include "scan/picture_module.hpp"

namespace tape::picture_module {

Failure decode(std::span<const std::uint8_t> bytes, Picture& out);
Failure encode(const Picture& picture, std::string_view format, int quality, std::vector<std::uint8_t>& out);
Failure greys(std::span<const std::uint8_t> bytes, Picture& luminance, Picture& darkest);
Failure blobs(const Picture& grey, Threshold how, int block, std::vector<scan::Blob>& out);

}  // namespace tape::picture_module
