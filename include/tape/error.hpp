// Typed errors and diagnostics of the tape library.
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
    parity,        ///< a frame whose holes fail the parity check
    not_in_code,   ///< a frame with good parity that is no character of the code
    unknown_code,  ///< the tape fits neither ISO nor EIA
    bad_image,     ///< an image file that does not follow its format
    bad_text,      ///< a text character the chosen code cannot carry
    bad_table,     ///< a code table file that cannot be read
    io,            ///< reading or writing failed
    usage,         ///< the caller asked for something impossible
};

/// Stable short name, e.g. "parity".
std::string_view errc_name(Errc code);

/// True for the kinds that mean "bad data in the input" (as opposed to I/O or usage).
bool is_data_error(Errc code);

/// Where on the tape or in the text something was found. Frames and lines are counted from 1.
struct Position {
    std::optional<std::uint64_t> frame{};
    std::optional<std::uint64_t> line{};
    std::optional<std::uint64_t> column{};

    /// "frame 137", "line 3, column 7", or "" when nothing is known.
    std::string describe() const;
};

/// A finding about damaged or unusual data. Damaged data is a value, not an exception.
struct Diagnostic {
    Errc code;
    Position where;
    std::string message;
};

/// Thrown for errors that stop an operation; carries the kind and the position.
class Error : public std::runtime_error {
public:
    Error(Errc code, Position where, const std::string& message)
        : std::runtime_error(message), code_(code), where_(where) {}
    Error(Errc code, const std::string& message) : Error(code, Position{}, message) {}
    explicit Error(const Diagnostic& d) : Error(d.code, d.where, d.message) {}

    Errc code() const noexcept { return code_; }
    const Position& where() const noexcept { return where_; }

private:
    Errc code_;
    Position where_;
};

}  // namespace tape
