// The frames of a restored image that its restoration left in doubt, kept beside the image: tape restore
// writes its JSON report (schema tape-restore/2, with the image's fingerprint) to IMAGE.restore.json, and
// every command that reads IMAGE names those frames, as it names bad frames. A frame in doubt whose
// every reading held parity reads as a good character: without this file nothing would tell. The file
// also lists the runs of equal frames whose length was decided against a read (not in doubt): where a
// wrong length could hide, and one more read would settle it.
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
    /// Not in doubt: a run's length the restoration decided against a read, by its odds or the program's
    /// rules (the reason says which).
    bool decided = false;

    /// Frames of the image before the place of the doubt: for one written, before its frame.
    std::uint64_t place() const { return left_out ? frame : frame - 1; }
    /// The doubt in words, as every command says it.
    std::string message() const;
};

/// Where the doubts of the image at image_path are kept: image_path + ".restore.json".
std::string doubts_file_for(std::string_view image_path);

/// The fingerprint the doubts file records for an image file's bytes: FNV-1a, 64 bits, in hex.
std::string image_fingerprint(std::span<const std::uint8_t> bytes);

/// What the doubts file beside an image holds for it.
struct DoubtsFile {
    /// Frames in doubt and runs decided against a read, sorted by place (one left out before a written
    /// one at the same place).
    std::vector<DoubtfulFrame> frames;
    /// Entries not read, each in words ("problem 4: its frame (1e+20) is no frame number"), and a file
    /// that is not the JSON restore writes: said, never read as something it is not.
    std::vector<std::string> refused;
};

/// The doubts file beside image_path, when it records the image as it now is (the fingerprint of its
/// bytes matches); empty when there is no such file or it is of another image. Never throws.
DoubtsFile read_doubts_beside(const std::string& image_path);
/// The same of JSON text already read, for the image's bytes.
DoubtsFile read_doubts(std::string_view json, std::span<const std::uint8_t> image);

/// The frames in doubt that the doubts file beside image_path records, written or left out, when it
/// records them for that image as it now is (the fingerprint of its bytes matches), sorted by place (one
/// left out before a written one at the same place); empty when there is no
/// such file, it is of another image (the image was changed since), or it cannot be read; entries that
/// cannot be read are left out (read_doubts_beside says them). Never throws.
std::vector<DoubtfulFrame> doubts_beside(const std::string& image_path);

}  // namespace tape
