// Encoder for the Elliott telecodes: each character looked up in the code's table (tape/telecode.hpp),
// which may hold characters that are not ASCII (£, ↑, ⑩) and aliases for what keyboards lack.
#include "tape/encode.hpp"
#include "tape/telecode.hpp"
#include "tape/utf8_text.hpp"
#include "utf8.hpp"

namespace tape {

void Encoder::encode_telecode(std::string_view text, std::vector<Frame>& out) {
    const TelecodeTable& table = *code_.telecode_table();
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
            ++i;  // CR LF in the text is one line end, as LF alone is
            continue;
        }
        std::string_view ch = utf8::char_at(text, i);
        auto cp = utf8::decode(ch);
        if (cp == U'\n' && options_.crlf) {
            auto cr = table.frame_of(U'\r');
            if (!cr) throw Error(Errc::usage, "the " + table.name() + " has no CR: --crlf cannot be punched in it");
            out.push_back(*cr);
        }
        auto frame = cp ? table.frame_of(*cp) : std::nullopt;
        if (!frame || *cp == 0) {
            auto first = static_cast<unsigned char>(ch[0]);
            std::string shown = first < 0x20 ? char_label(ch[0]) : "'" + visible(ch) + "'";
            throw Error(Errc::bad_text, position_, shown + " cannot be punched in the " + table.name());
        }
        out.push_back(*frame);
        if (*cp == U'\n') {
            ++*position_.line;
            position_.column = 1;
        } else {
            ++*position_.column;
        }
        i += ch.size();
    }
}

}  // namespace tape
