// Decoding: frames -> characters, with every bad frame reported by its frame number.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tape/charset.hpp"
#include "tape/code.hpp"
#include "tape/error.hpp"
#include "tape/frame.hpp"

namespace tape {

/// Put in the text, with --keep-going, where a frame could not be read: U+FFFD REPLACEMENT CHARACTER.
/// It is no ISO character, so a marked text cannot be punched again by mistake.
inline constexpr std::string_view bad_frame_marker = "\xEF\xBF\xBD";

struct DecodeOptions {
    Code code = Code::iso;
    Parity parity = Parity::even;        ///< ISO only; EIA parity is fixed (odd, track 5)
    Charset charset = Charset::ascii;
    bool keep_going = false;             ///< report every bad frame instead of stopping at the first
    bool positions = false;              ///< fill DecodeResult::frame_of
    const CodeTable* eia_table = nullptr;///< a corrected EIA table; nullptr = built-in
};

struct DecodeResult {
    std::string text;                    ///< the characters, UTF-8; LF ends a block
    std::vector<std::uint64_t> frame_of; ///< with positions: 0-based frame index of each byte of text
    std::vector<Diagnostic> diagnostics; ///< one per bad frame, in tape order
    bool complete = true;                ///< false when decoding stopped at the first bad frame

    bool ok() const { return diagnostics.empty(); }
};

/// Decodes a whole tape. Blank frames and DEL are skipped; each frame that fails the parity rule
/// or is no character of the code gives a Diagnostic (Errc::parity / Errc::not_in_code) and stops
/// the decoding unless keep_going, in which case the frame is marked in the text.
DecodeResult decode(std::span<const Frame> frames, const DecodeOptions& options);

/// The hot loop, for callers that bring their own buffer. Decodes frames into out (room for
/// frames.size() bytes, 7-bit characters, no positions) until the first frame that is neither a
/// character, blank nor DEL. Returns that frame's index, or frames.size(); *written = bytes stored.
std::size_t decode_run(const FrameCode& code, std::span<const Frame> frames, char* out, std::size_t* written);

/// The diagnostic for a bad frame at 0-based index.
Diagnostic bad_frame_diagnostic(const FrameCode& code, Frame f, std::uint64_t index);

}  // namespace tape
