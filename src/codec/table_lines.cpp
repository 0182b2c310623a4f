// The line format the code tables share (table_lines.hpp).
#include "table_lines.hpp"

namespace tape {

TableLines::TableLines(std::string_view text, TableComments comments) : in_(std::string(text)), comments_(comments) {}

bool TableLines::next() {
    while (std::getline(in_, line_)) {
        ++number_;
        fields_.clear();
        std::istringstream words(line_);
        for (std::string word; words >> word;) {
            if (word[0] == '#' && (comments_ == TableComments::any_field || fields_.empty())) break;
            fields_.push_back(word);
        }
        if (!fields_.empty()) return true;
    }
    return false;
}

std::string TableLines::rest() const {
    std::string rest = line_.substr(line_.find(fields_[0]) + fields_[0].size());
    rest.erase(0, rest.find_first_not_of(" \t"));
    rest.erase(rest.find_last_not_of(" \t\r") + 1);
    return rest;
}

}  // namespace tape
