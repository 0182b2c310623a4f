// Picture file names (tape/picture.hpp): what the extension says the file is.
#include <algorithm>
#include <cctype>
#include <string>

#include "tape/picture.hpp"

namespace tape {

std::string_view picture_format_for_path(std::string_view path) {
    auto dot = path.rfind('.');
    if (dot == std::string_view::npos || path.find('/', dot) != std::string_view::npos) return "";
    std::string ext(path.substr(dot + 1));
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == "png") return "png";
    if (ext == "jpg" || ext == "jpeg") return "jpeg";
    if (ext == "tif" || ext == "tiff") return "tiff";
    return "";
}

}  // namespace tape
