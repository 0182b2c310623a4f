// The line format of the code tables read as data (data/ita2.tab, data/mtk2.tab, data/elliott900.tab,
// data/elliott920.tab): one entry a line, its fields split at white space, blank lines and comments left
// out. The tables differ only in where a '#' starts a comment, so that is the caller's choice.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace tape {

/// Where a '#' starts a comment.
enum class TableComments {
    any_field,    ///< at any field: the rest of the line is left out (the 5-track tables)
    first_field,  ///< only as a line's first field; elsewhere '#' is a character (the telecodes punch it)
};

/// The lines of a table's text that hold fields, one at a time:
///     TableLines lines(text, TableComments::any_field);
///     while (lines.next()) use(lines.number(), lines.fields());
/// Keeps a copy of the text.
class TableLines {
public:
    TableLines(std::string_view text, TableComments comments);

    /// Moves to the next line that holds fields; false at the end of the text.
    bool next();
    /// The line's number, from 1; after the end, the number of lines in the text (0 for none).
    std::uint64_t number() const { return number_; }
    /// The line's fields, without the comment; never empty after next() returned true.
    const std::vector<std::string>& fields() const { return fields_; }
    /// The line after its first field, without the white space around it (a name of several words).
    std::string rest() const;

private:
    std::istringstream in_;
    TableComments comments_;
    std::string line_;
    std::vector<std::string> fields_;
    std::uint64_t number_ = 0;
};

}  // namespace tape
