// What a control asks of the DNC service by punching out a short program: (PRG=NAME), several names
// separated by commas, or (RESTART=NAME,N50). Everything from a line is untrusted: names are checked,
// then looked up among the library's files, never joined into a path.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tape::dnc {

/// The longest name a control may ask for.
inline constexpr std::size_t max_name_length = 64;

struct Request {
    enum class Kind { programs, restart };
    Kind kind = Kind::programs;
    std::string comment;               ///< the request as punched, made printable and cut to 80 characters
    std::vector<std::string> names;    ///< names that may be looked up, in the order asked
    std::vector<std::string> refused;  ///< "'../x': a path ...", one for each name refused
    std::string block;                 ///< restart: the block, "N50"
};

/// The request a punch-out's text is: one (PRG=...) or (RESTART=...) comment and nothing else but
/// '%', blanks, line ends (or ';'), a program number (O1234, :1234, %1234) and a program's end (M02,
/// M30, M99) each on a block of its own or beside the comment, block numbers allowed. Anything more
/// and the text is a program: nullopt. Keys are read in either case, blanks around names ignored;
/// empty names are counted in one refusal, and past 8 refusals the rest are counted. Never throws.
std::optional<Request> parse_request(std::string_view text);

/// The first request comment anywhere in text, whatever stands around it (for saying that a program
/// holds one); where it opens and closes when asked. Never throws.
std::optional<Request> request_comment_in(std::string_view text, std::size_t* open_at = nullptr,
                                          std::size_t* close_at = nullptr);

/// Why a name from a line may not be looked up ("" when it may): empty, over max_name_length, holding
/// NUL, '/', '\\' or "..", starting with '.', or holding anything but letters, digits, '_', '-', '.'.
std::string name_problem(std::string_view name);

/// What a library lookup found: the file, or why there is none.
struct Found {
    std::string path;     ///< empty when not found
    std::string problem;  ///< "not in the library", "ambiguous: ..."
};

/// Finds name among the regular files of folder (symbolic links are none: never followed): a file named so or with that
/// stem (exact, then in either case), else the one file whose program number (O1234, :1234 or the ГОСТ number after
/// '%'; leading zeros ignored) is name. Two candidates at the same step are ambiguous: nothing is chosen.
Found find_program(const std::string& folder, std::string_view name);

/// The text of a library file find_program found, read without following a symbolic link (one put
/// in its place since is refused). Throws Error(Errc::io) naming path when it cannot be read or is no
/// regular file.
std::string read_program(const std::string& path);

/// The program number of a program's text ("O1234", or the ГОСТ number after '%'), made into a file
/// name's stem; nullopt when it has none that is a safe name.
std::optional<std::string> program_file_stem(std::string_view text);

}  // namespace tape::dnc
