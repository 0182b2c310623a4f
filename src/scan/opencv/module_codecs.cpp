// The picture module's files (picture_module.hpp): PNG, JPEG and TIFF through OpenCV's imgcodecs.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "scan/opencv/module_parts.hpp"

namespace tape::picture_module {
namespace {

// libpng says its errors on standard error itself ("libpng error: IHDR: CRC error") before OpenCV turns
// them into an empty picture, which is said in words below: standard error points at /dev/null while a
// picture is decoded (the program says nothing meanwhile).
class QuietStandardError {
public:
    QuietStandardError() {
        std::fflush(stderr);
        saved_ = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
        int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved_ >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
        if (null >= 0) ::close(null);
    }
    ~QuietStandardError() {
        if (saved_ < 0) return;
        std::fflush(stderr);
        ::dup2(saved_, STDERR_FILENO);
        ::close(saved_);
    }
    QuietStandardError(const QuietStandardError&) = delete;
    QuietStandardError& operator=(const QuietStandardError&) = delete;

private:
    int saved_ = -1;
};

cv::Mat decoded(std::span<const std::uint8_t> bytes, Failure& failure) {
    cv::Mat m;
    QuietStandardError quiet;
    try {
        m = cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(bytes.data())),
                         cv::IMREAD_COLOR);
    } catch (const cv::Exception&) {
        // OpenCV's message names its source lines and assertions, nothing a machinist can act on.
        failure = {Errc::bad_image, "the picture cannot be decoded: its data is damaged or cut short"};
        return {};
    }
    if (m.empty()) failure = {Errc::bad_image, "the picture cannot be decoded: its data is damaged or cut short"};
    return m;
}

Picture grey_picture(int width, int height) {
    return Picture{width, height, 1, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height)};
}

}  // namespace

Failure decode(std::span<const std::uint8_t> bytes, Picture& out) {
    Failure failure;
    cv::Mat m = decoded(bytes, failure);
    if (failure) return failure;
    out = Picture{m.cols, m.rows, 3, {}};
    out.pixels.resize(static_cast<std::size_t>(m.cols) * m.rows * 3);
    for (int y = 0; y < m.rows; ++y) std::copy_n(m.ptr<std::uint8_t>(y), m.cols * 3, out.at(0, y));
    return {};
}

Failure encode(const Picture& p, std::string_view format, int quality, std::vector<std::uint8_t>& out) {
    std::string ext = format == "png" ? ".png" : format == "jpeg" ? ".jpg" : format == "tiff" ? ".tif" : "";
    if (ext.empty()) return {Errc::usage, "pictures are written as png, jpeg or tiff, not " + std::string(format)};
    if (p.channels != 1 && p.channels != 3) return {Errc::usage, "a picture has 1 or 3 channels"};
    cv::Mat m(p.height, p.width, p.channels == 1 ? CV_8UC1 : CV_8UC3, const_cast<std::uint8_t*>(p.pixels.data()));
    std::vector<int> params;
    if (format == "jpeg") params = {cv::IMWRITE_JPEG_QUALITY, std::clamp(quality, 1, 100)};
    if (format == "png") params = {cv::IMWRITE_PNG_COMPRESSION, 1};  // fast: test pictures are large and noisy
    try {
        if (!cv::imencode(ext, m, out, params)) return {Errc::io, "the " + std::string(format) + " encoder failed"};
    } catch (const cv::Exception& e) {
        return {Errc::io, "cannot encode the picture as " + std::string(format) + ": " + e.msg};
    }
    return {};
}

// The darkest channel tells coloured paper (orange, red, yellow) from a grey or white backing far better
// than the luminance does; made row by row, with no copy of the colours on the side.
Failure greys(std::span<const std::uint8_t> bytes, Picture& luminance, Picture& darkest) {
    Failure failure;
    cv::Mat colour = decoded(bytes, failure);
    failure.code = Errc::io;  // scan: a file it cannot read as a picture is an input it cannot read (exit 3)
    if (failure) return failure;
    luminance = grey_picture(colour.cols, colour.rows);
    darkest = grey_picture(colour.cols, colour.rows);
    cv::Mat lum(colour.rows, colour.cols, CV_8UC1, luminance.pixels.data());
    cv::cvtColor(colour, lum, cv::COLOR_BGR2GRAY);
    for (int y = 0; y < colour.rows; ++y) {
        const std::uint8_t* c = colour.ptr<std::uint8_t>(y);
        std::uint8_t* m = darkest.at(0, y);
        for (int x = 0; x < colour.cols; ++x, c += 3) m[x] = std::min({c[0], c[1], c[2]});
    }
    return {};
}

}  // namespace tape::picture_module
