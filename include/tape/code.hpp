// Frame codes: how frames on tape stand for characters (ISO 7-bit with a parity track, EIA RS-244; the
// 5-track telegraph codes ITA2 and МТК-2, whose shifts tape/five_track.hpp follows; the Elliott 900 and
// 920 telecodes of tape/telecode.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "tape/frame.hpp"

namespace tape {

enum class Code {
    iso,         ///< ISO 7-bit, parity on track 8
    eia,         ///< EIA RS-244, odd parity on track 5
    ita2,        ///< 5-track ITA2 (CCITT No. 2): letters and figures registers
    mtk2,        ///< 5-track МТК-2: ITA2 with a Russian register
    elliott900,  ///< Elliott 900 telecode: ASCII of its time, even parity on track 8, £ for #
    elliott920,  ///< Elliott 920 telecode: even parity on track 5, a character set of its own
};

class FiveTrackTable;
class TelecodeTable;

/// True for the 5-track telegraph codes: a frame is 5 bits, and what it means depends on the last shift.
constexpr bool is_five_track(Code c) { return c == Code::ita2 || c == Code::mtk2; }
/// True for the computer makers' 8-track codes read from a table (tape/telecode.hpp).
constexpr bool is_telecode(Code c) { return c == Code::elliott900 || c == Code::elliott920; }

/// The rule for track 8 of an ISO/ASCII tape. NC tapes use even; DEC-era ASCII tapes often mark.
enum class Parity {
    even,   ///< track 8 makes the number of holes even (ISO 840, ГОСТ 13052-74)
    odd,    ///< track 8 makes the number of holes odd
    mark,   ///< track 8 always punched
    space,  ///< track 8 never punched
    none,   ///< track 8 ignored
};

/// "iso", "eia", "ita2", "mtk2", "elliott900", "elliott920".
std::string_view code_name(Code c);
std::string_view parity_name(Parity p);
std::optional<Code> parse_code(std::string_view name);
/// Every code, in the order of the enum.
std::span<const Code> all_codes();
std::optional<Parity> parse_parity(std::string_view name);

/// A code table read from data: each entry maps one ISO character to one frame.
/// The EIA table lives in data/eia-rs244.tab; its text is compiled in and may be replaced at run time.
class CodeTable {
public:
    /// Reads the table text (format in data/eia-rs244.tab). Throws Error(Errc::bad_table) with the
    /// line of a malformed entry, of a frame or character given twice, or of an even-parity frame.
    static CodeTable parse(std::string_view text);

    /// The built-in EIA RS-244 table.
    static const CodeTable& builtin_eia();

    /// Frame for an ISO character (0..127), or nullopt when the table has none.
    std::optional<Frame> frame_for(char c) const;
    /// ISO character for a frame, or nullopt when no entry uses it. NUL stands for blank tape.
    std::optional<char> char_for(Frame f) const;

private:
    std::array<std::int16_t, 128> frame_of_char_{};
    std::array<std::int16_t, 256> char_of_frame_{};
};

/// What one frame means under a FrameCode.
enum class FrameKind : std::int8_t {
    character,     ///< a character to pass on
    blank,         ///< blank tape (NUL, ПУС): skipped
    rubout,        ///< DEL (ЗБ): skipped wherever it stands
    parity_error,  ///< the holes fail the code's parity rule
    not_in_code,   ///< good parity but no character of this code
};

/// True for the frames a reader reports: one failing parity, or one that is no character of the code.
inline bool is_bad_frame(FrameKind k) { return k == FrameKind::parity_error || k == FrameKind::not_in_code; }

/// One frame code with its parity rule, as two lookup tables built once.
/// Cheap to copy; the decoder, encoder, survey and the holes writer all read frames through it.
class FrameCode {
public:
    /// ISO 7-bit positions on tracks 1-7, track 8 by the parity rule.
    static FrameCode iso(Parity parity = Parity::even);
    /// EIA RS-244 from a table (the built-in one unless a corrected copy is given).
    static FrameCode eia(const CodeTable& table = CodeTable::builtin_eia());
    /// A 5-track code: every frame of tracks 1-5 is a character (blank tape too in МТК-2, where it is the
    /// Russian shift), frames with tracks 6-8 are not_in_code. character() is the letters register's
    /// (CR, LF and SP are the same in all): the text comes from the Decoder, which follows the shifts.
    static FrameCode five_track(Code code);
    /// An Elliott telecode from its table: even parity over all eight tracks, a character for each value
    /// the table lists. character() of a character that is not one ASCII byte is 0x81 + its index in
    /// TelecodeTable::wide_characters(); text() gives it whole.
    static FrameCode telecode(Code code);
    static FrameCode make(Code code, Parity parity, const CodeTable* eia_table = nullptr);

    Code code() const { return code_; }
    /// The table of a 5-track code, nullptr for ISO and EIA.
    const FiveTrackTable* five_track_table() const { return five_track_; }
    /// The table of a telecode, nullptr for the others.
    const TelecodeTable* telecode_table() const { return telecode_; }
    Parity parity() const { return parity_; }

    FrameKind kind(Frame f) const { return static_cast<FrameKind>(kind_[f]); }
    /// The ISO character (7-bit) of a frame of kind character.
    char character(Frame f) const { return static_cast<char>(char_[f]); }
    /// The telecode character a byte from character() stands for when it is not ASCII (0x81 on), else "".
    std::string_view wide_character(unsigned char byte) const;
    /// The frame that carries ISO character c (or a telecode's byte for a wide character), or nullopt
    /// when this code cannot carry it.
    std::optional<Frame> frame_for(unsigned char c) const;

    /// Short label for listings: "%", "LF", "NUL", "DEL", "SP", "parity error", "not EIA"; for a 5-track
    /// frame its meaning in every register ("A/-"): FiveTrackLabeler follows the shifts instead.
    std::string label(Frame f) const;

private:
    Code code_ = Code::iso;
    Parity parity_ = Parity::even;
    std::array<std::int8_t, 256> kind_{};
    std::array<std::uint8_t, 256> char_{};
    std::array<std::int16_t, 256> frame_{};
    const FiveTrackTable* five_track_ = nullptr;
    const TelecodeTable* telecode_ = nullptr;
};

/// Name of an ISO control character ("LF", "NUL"...) or the character itself.
std::string char_label(char c);

}  // namespace tape
