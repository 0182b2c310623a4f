// Encoding: a text program -> frames, with blank leader and trailer.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "tape/charset.hpp"
#include "tape/code.hpp"
#include "tape/frame.hpp"

namespace tape {

inline constexpr std::size_t default_leader = 100;  ///< blank frames, 254 mm of tape
inline constexpr std::size_t default_trailer = 100;

struct EncodeOptions {
    Code code = Code::iso;
    Parity parity = Parity::even;        ///< ISO only
    Charset charset = Charset::ascii;
    std::size_t leader = default_leader;
    std::size_t trailer = default_trailer;
    bool crlf = false;                   ///< CR LF on tape at the end of each block (ISO only)
    const CodeTable* eia_table = nullptr;///< a corrected EIA table; nullptr = built-in
};

/// Each text line is a block: LF or CR LF in the text, LF (EIA: EOB) on tape.
/// Throws Error(Errc::bad_text) naming line and column of the first character the code cannot carry.
std::vector<Frame> encode(std::string_view text, const EncodeOptions& options);

/// The hot loop: 7-bit characters -> frames into out (room for chars.size() frames).
/// Returns the index of the first character the code cannot carry, or chars.size().
std::size_t encode_run(const FrameCode& code, std::string_view chars, Frame* out);

}  // namespace tape
