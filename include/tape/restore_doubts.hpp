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

/// A frame of an image in doubt, with the restoration's status and reason: one written (at frame), or
/// one the restoration left out (after frame; 0: before the first).
struct DoubtfulFrame {
    std::uint64_t frame = 0;  ///< 1-based; for one left out, the frame it would have followed
    std::string status;       ///< "contested", "guessed", ...
    std::string reason;
    bool left_out = false;

    /// Frames of the image before the place of the doubt: for one written, before its frame.
    std::uint64_t place() const { return left_out ? frame : frame - 1; }
    /// The doubt in words, as every command says it.
    std::string message() const;
};

/// Where the doubts of the image at image_path are kept: image_path + ".restore.json".
std::string doubts_file_for(std::string_view image_path);

/// The fingerprint the doubts file records for an image file's bytes: FNV-1a, 64 bits, in hex.
std::string image_fingerprint(std::span<const std::uint8_t> bytes);

/// The frames in doubt that the doubts file beside image_path records, written or left out, when it
/// records them for that image as it now is (the fingerprint of its bytes matches), sorted by place (one
/// left out before a written one at the same place); empty when there is no
/// such file, it is of another image (the image was changed since), or it cannot be read. Never throws.
std::vector<DoubtfulFrame> doubts_beside(const std::string& image_path);

}  // namespace tape
