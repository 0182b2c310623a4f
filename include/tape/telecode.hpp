// Computer makers' 8-track telegraph codes as table data: the Elliott 900 and 920 telecodes. A frame
// holds a 7-bit code value on seven tracks and even parity on the eighth; each value stands for one
// character, which need not be ASCII (£, º, ↑, the 920's ⑩ and ⑪). The tables live in
// data/elliott900.tab and data/elliott920.tab (their format and sources are in the files).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/code.hpp"
#include "tape/frame.hpp"

namespace tape {

class TelecodeTable {
public:
    /// What a frame with even parity means.
    enum class Kind : std::uint8_t {
        none,       ///< no character of the code: a finding when read
        blank,      ///< blank tape: skipped
        rubout,     ///< erase (all holes): skipped
        character,  ///< text
    };
    struct Entry {
        Kind kind = Kind::none;
        std::string text;      ///< the character, UTF-8 (LF, CR, HT as themselves)
        std::uint8_t value{};  ///< the 7-bit code value, as the charts number it
    };

    /// Reads a table (format in data/elliott920.tab). Throws Error(Errc::bad_table) with the line of a
    /// malformed entry, of a value or character given twice, of tracks that are not seven distinct
    /// tracks beside the parity track; or for a table without name, tracks, parity, blank or LF.
    static TelecodeTable parse(std::string_view text);
    /// The built-in table of code (elliott900, elliott920); throws std::logic_error for another code.
    static const TelecodeTable& builtin(Code code);

    /// "Elliott 920 telecode".
    const std::string& name() const { return name_; }
    /// What frame f means; frames with an odd number of holes are parity errors, entry() says none.
    const Entry& entry(Frame f) const { return entries_[f]; }
    /// The frame that carries a character (an alias too), or nullopt.
    std::optional<Frame> frame_of(char32_t c) const;
    /// The frame of a 7-bit code value, parity track included.
    Frame frame_of_value(std::uint8_t value) const;
    /// The characters that are not one ASCII byte, in a fixed order: FrameCode carries them as the
    /// bytes 0x81 + their index, so that the decoder's byte loops pass them through.
    const std::vector<std::string>& wide_characters() const { return wide_; }

private:
    std::string name_;
    std::array<int, 7> value_tracks_{};
    int parity_track_ = 0;
    std::array<Entry, 256> entries_{};
    std::map<char32_t, Frame> frames_;
    std::vector<std::string> wide_;
};

}  // namespace tape
