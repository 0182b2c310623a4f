// Typed errors and the one diagnostic type of the tape library: codec, image formats, loader, lint
// and devices all report through it.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

/// Every error kind has a stable short name (errc_name) and belongs to one exit class.
enum class Errc {
    parity,          ///< a frame whose holes fail the parity check
    not_in_code,     ///< a frame with good parity that is no character of the code
    unknown_code,    ///< the tape fits neither ISO nor EIA
    bad_image,       ///< an image file that does not follow its format
    bad_text,        ///< a text character the chosen code cannot carry
    bad_table,       ///< a code table file that cannot be read
    bad_program,     ///< a program that breaks a rule of ГОСТ 20999-83 or of a controller format
    io,              ///< reading or writing failed
    usage,           ///< the caller asked for something impossible
    exists,          ///< an output that already exists and may not be replaced
    doubtful_frame,  ///< a frame the reader itself doubts: read without a sprocket, mistimed, a level near its
                     ///< threshold
    blank_frame,     ///< blank tape inside a block: a character whose holes were all lost reads so
};

/// Stable short name, e.g. "parity".
std::string_view errc_name(Errc code);

/// True for the kinds that mean "bad data in the input" (as opposed to I/O or usage).
bool is_data_error(Errc code);
/// True for the kinds of a bad frame on tape (parity, not in the code).
bool is_bad_frame(Errc code);

enum class Severity { note, warning, error };
/// "note", "warning", "error".
std::string_view severity_name(Severity s);

/// Where something was found, as far as it is known. Frames, lines, columns, blocks and programs are
/// counted from 1, byte offsets (into the text or the image file) from 0.
struct Position {
    std::optional<std::uint64_t> frame{};
    std::optional<std::uint64_t> line{};
    std::optional<std::uint64_t> column{};
    std::optional<std::uint64_t> byte{};
    std::optional<std::uint64_t> block{};
    std::optional<std::uint64_t> program{};

    /// "frame 137", "line 3, column 7", or "" when neither is known.
    std::string describe() const;
};

/// What the user could do about a diagnostic, in the data's terms: the program showing the message
/// says it in its own (the command line names its options, a GUI its buttons).
struct Hint {
    enum class Action {
        none,
        replace_output,       ///< allow the output to be replaced
        use_charset,          ///< encode with character set `value` ("koi7")
        use_iso_parity,       ///< read as ISO with parity `value` ("odd", "mark", "space", "none")
        read_as_image,        ///< read the input as a tape image, not as a text program
        give_source_format,   ///< say which format the program is written in (for implied points)
        use_code,             ///< read or punch in code `value` ("iso", "eia", "mtk2")
        use_five_track_code,  ///< read as a 5-track tape (ITA2, МТК-2)
        encode_text,          ///< the input is a text program: encode it rather than decode it
    };
    Action action = Action::none;
    std::string_view value{};

    explicit operator bool() const { return action != Action::none; }
};

/// A finding about damaged or unusual data, from any layer. Damaged data is a value, not an
/// exception. The stable id is the rule's for program findings and the kind's name otherwise.
struct Diagnostic {
    Errc code = Errc::bad_program;
    Position where{};
    std::string message{};
    std::string_view rule{};  ///< the program rule broken ("word-order"); empty for the codec's kinds
    Severity severity = Severity::error;
    Hint hint{};

    /// The stable id: rule, or errc_name(code).
    std::string_view id() const { return rule.empty() ? errc_name(code) : rule; }
};

/// Thrown for errors that stop an operation; carries the kind, the position and a hint.
class Error : public std::runtime_error {
public:
    Error(Errc code, Position where, const std::string& message, Hint hint = {})
        : std::runtime_error(message), code_(code), where_(where), hint_(hint) {}
    Error(Errc code, const std::string& message, Hint hint = {}) : Error(code, Position{}, message, hint) {}
    explicit Error(const Diagnostic& d) : Error(d.code, d.where, d.message, d.hint) {}

    Errc code() const noexcept { return code_; }
    const Position& where() const noexcept { return where_; }
    const Hint& hint() const noexcept { return hint_; }

private:
    Errc code_;
    Position where_;
    Hint hint_;
};

}  // namespace tape
