// The frames of a restored image that its restoration left in doubt, kept beside the image: tape restore
// writes its JSON report (schema tape-restore/2, with the image's fingerprint) to IMAGE.restore.json, and
// every command that reads IMAGE names those frames, as it names bad frames. A frame in doubt whose
// every reading held parity reads as a good character: without this file nothing would tell.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

/// A frame of an image in doubt, with the restoration's status and reason.
struct DoubtfulFrame {
    std::uint64_t frame = 0;  ///< 1-based
    std::string status;       ///< "contested", "guessed", ...
    std::string reason;
};

/// Where the doubts of the image at image_path are kept: image_path + ".restore.json".
std::string doubts_file_for(std::string_view image_path);

/// The fingerprint the doubts file records for an image file's bytes: FNV-1a, 64 bits, in hex.
std::string image_fingerprint(std::span<const std::uint8_t> bytes);

/// The frames in doubt that the doubts file beside image_path records, when it records them for that
/// image as it now is (the fingerprint of its bytes matches), sorted by frame; empty when there is no
/// such file, it is of another image (the image was changed since), or it cannot be read. Never throws.
std::vector<DoubtfulFrame> doubts_beside(const std::string& image_path);

}  // namespace tape
