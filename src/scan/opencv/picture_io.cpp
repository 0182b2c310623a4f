// Picture files through OpenCV's imgcodecs (tape/picture.hpp).
#include <algorithm>
#include <opencv2/imgcodecs.hpp>

#include "tape/error.hpp"
#include "tape/picture.hpp"

namespace tape {

std::vector<std::uint8_t> encode_picture(const Picture& p, std::string_view format, int quality) {
    std::string ext = format == "png" ? ".png" : format == "jpeg" ? ".jpg" : format == "tiff" ? ".tif" : "";
    if (ext.empty()) throw Error(Errc::usage, "pictures are written as png, jpeg or tiff, not " + std::string(format));
    if (p.channels != 1 && p.channels != 3) throw Error(Errc::usage, "a picture has 1 or 3 channels");
    cv::Mat m(p.height, p.width, p.channels == 1 ? CV_8UC1 : CV_8UC3, const_cast<std::uint8_t*>(p.pixels.data()));
    std::vector<int> params;
    if (format == "jpeg") params = {cv::IMWRITE_JPEG_QUALITY, std::clamp(quality, 1, 100)};
    if (format == "png") params = {cv::IMWRITE_PNG_COMPRESSION, 1};  // fast: test pictures are large and noisy
    std::vector<std::uint8_t> out;
    try {
        if (!cv::imencode(ext, m, out, params)) throw Error(Errc::io, "the " + std::string(format) + " encoder failed");
    } catch (const cv::Exception& e) {
        throw Error(Errc::io, "cannot encode the picture as " + std::string(format) + ": " + e.msg);
    }
    return out;
}

Picture decode_picture(std::span<const std::uint8_t> bytes) {
    cv::Mat m;
    try {
        m = cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(bytes.data())),
                         cv::IMREAD_COLOR);
    } catch (const cv::Exception& e) {
        throw Error(Errc::bad_image, "cannot decode the picture: " + e.msg);
    }
    if (m.empty()) throw Error(Errc::bad_image, "not a picture OpenCV can read (PNG, JPEG, TIFF, ...)");
    Picture p{m.cols, m.rows, 3, {}};
    p.pixels.resize(static_cast<std::size_t>(m.cols) * m.rows * 3);
    for (int y = 0; y < m.rows; ++y) std::copy_n(m.ptr<std::uint8_t>(y), m.cols * 3, p.at(0, y));
    return p;
}

}  // namespace tape
