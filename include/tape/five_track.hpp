// 5-track telegraph codes (ITA2, МТК-2) as table data: registers switched by shift frames, what each
// frame means in each register. The tables live in data/ita2.tab and data/mtk2.tab (spec section 4b).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/frame.hpp"

namespace tape {

/// The frames of 5-track tape: bit 0 = track 1 ... bit 4 = track 5; bits 5-7 are never punched.
inline constexpr Frame five_track_frames = 0x20;

class FiveTrackTable {
public:
    static constexpr int max_registers = 3;

    /// What a frame means in one register.
    enum class Kind : std::uint8_t {
        character,  ///< text: a UTF-8 character, or "\r" / "\n" for CR / LF
        shift,      ///< selects register `shift`, no text
        blank,      ///< blank tape: skipped
        none,       ///< no agreed character (ITA2 national positions): a finding when read
    };
    struct Meaning {
        Kind kind = Kind::none;
        std::uint8_t shift = 0;
        std::string text;
    };
    /// Where a character is punched: its frame, and the register it needs (nullopt: any register).
    struct Place {
        std::optional<std::uint8_t> shift;
        Frame frame = 0;
    };

    /// Reads a table (format in data/ita2.tab). Throws Error(Errc::bad_table) with the line of a
    /// malformed entry, of a frame or character given twice; or for a frame or shift left out.
    static FiveTrackTable parse(std::string_view text);
    /// The built-in tables.
    static const FiveTrackTable& builtin_ita2();
    static const FiveTrackTable& builtin_mtk2();

    int registers() const { return registers_; }
    /// "LTRS", "FIGS", "RUS".
    std::string_view register_name(int r) const { return register_names_[static_cast<std::size_t>(r)]; }
    Frame shift_frame(int r) const { return shift_frames_[static_cast<std::size_t>(r)]; }
    /// What frame f (below five_track_frames) means in register r.
    const Meaning& meaning(int r, Frame f) const { return meanings_[static_cast<std::size_t>(r)][f]; }
    /// Where a character (a code point) is punched, or nullopt when the code cannot carry it.
    std::optional<Place> place_of(char32_t c) const;
    /// Short label for listings in register r: "A", "Я", "SP", "CR", "LF", "LTRS", "BLANK", "national".
    std::string label(int r, Frame f) const;

private:
    class Reader;  // five_track_table.cpp: parse() in its steps

    int registers_ = 0;
    std::array<std::string, max_registers> register_names_{};
    std::array<Frame, max_registers> shift_frames_{};
    std::array<std::array<Meaning, five_track_frames>, max_registers> meanings_{};
    std::map<char32_t, Place> places_;
};

/// Follows the register of a 5-track tape frame by frame, for listings: the label of each frame in
/// the register it is read in ("LTRS", "A", "5").
class FiveTrackLabeler {
public:
    explicit FiveTrackLabeler(const FiveTrackTable& table) : table_(&table) {}
    /// The label of the next frame; a shift frame changes the register for the frames after it.
    std::string next(Frame f);
    /// True when the next frame, f, would be reported by the decoder: tracks 6-8, or no agreed character.
    bool bad(Frame f) const {
        return f >= five_track_frames || table_->meaning(register_, f).kind == FiveTrackTable::Kind::none;
    }

private:
    const FiveTrackTable* table_;
    int register_ = 0;
};

}  // namespace tape
