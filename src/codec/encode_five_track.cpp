// Encoder for the 5-track telegraph codes (ITA2, МТК-2): each character is looked up in the code's
// table, and a shift frame goes before it when it needs another register than the tape is in.
#include "tape/encode.hpp"
#include "tape/five_track.hpp"
#include "tape/utf8_text.hpp"
#include "utf8.hpp"

namespace tape {
namespace {

// 5-track codes have no case: a lower-case letter is punched as its capital.
char32_t capital(char32_t c) {
    if (c >= U'a' && c <= U'z') return c - U'a' + U'A';
    if (c >= U'а' && c <= U'я') return c - U'а' + U'А';
    if (c == U'ё') return U'Ё';
    return c;
}

std::string_view code_title(Code code) { return code == Code::mtk2 ? "МТК-2" : "ITA2"; }

[[noreturn]] void cannot_punch(std::string_view ch, Position where, Code code) {
    auto first = static_cast<unsigned char>(ch[0]);
    std::string shown = first < 0x20 ? char_label(ch[0]) : "'" + visible(ch) + "'";
    std::string why = shown + " cannot be punched in " + std::string(code_title(code)) + " code";
    Hint hint;
    auto cp = utf8::decode(ch);
    if (cp && (*cp == U'Ё' || *cp == U'ё'))
        why += " (МТК-2 has no Ё: write Е)";
    else if (cp && (*cp == U'Ъ' || *cp == U'ъ'))
        why += " (МТК-2 has no Ъ: write Ь)";
    else if (cp && code == Code::ita2 && FiveTrackTable::builtin_mtk2().place_of(capital(*cp))) {
        why += "; Russian needs МТК-2";
        hint = Hint{Hint::Action::use_code, "mtk2"};
    }
    throw Error(Errc::bad_text, where, why, hint);
}

}  // namespace

void Encoder::encode_five_track(std::string_view text, std::vector<Frame>& out) {
    const FiveTrackTable& table = *code_.five_track_table();
    auto punch = [&](const FiveTrackTable::Place& p) {
        if (p.shift && *p.shift != register_) {
            out.push_back(table.shift_frame(*p.shift));
            register_ = *p.shift;
        }
        out.push_back(p.frame);
    };
    const auto cr = table.place_of(U'\r'), lf = table.place_of(U'\n');
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
            ++i;  // CR LF in the text is one line end, as LF alone is
            continue;
        }
        if (text[i] == '\n') {
            // The teleprinter's line end: the carriage back, then the paper up.
            if (cr) punch(*cr);
            punch(*lf);
            ++*position_.line;
            position_.column = 1;
            ++i;
            continue;
        }
        std::string_view ch = utf8::char_at(text, i);
        auto cp = utf8::decode(ch);
        std::optional<FiveTrackTable::Place> place;
        if (cp) place = table.place_of(*cp);
        if (cp && !place) place = table.place_of(capital(*cp));
        if (!place) cannot_punch(ch, position_, options_.code);
        punch(*place);
        // Teleprinters with unshift-on-space return to letters at a space: the figure after it gets its
        // shift again, so that the tape reads the same on them and on the others.
        if (*cp == U' ' && register_ >= 0 && table.register_name(register_) == "FIGS") register_ = -1;
        ++*position_.column;
        i += ch.size();
    }
}

}  // namespace tape
