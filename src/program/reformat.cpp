#include "tape/reformat.hpp"

#include "tape/lint.hpp"

namespace tape {

std::string reformat(const LoadedTape& tape, const ReformatOptions& o, std::vector<Diagnostic>& findings) {
    if (!o.spec) throw Error(Errc::usage, "no controller format to write the program for");
    const std::string sep = o.spaces ? " " : "";
    std::string text = tape.label;
    for (const auto& p : tape.programs) {
        if (!o.from && !uses_explicit_points(p)) {
            Finding f = program_finding("implied-point", p.start, 0,
                                        "the program writes no decimal point: its numbers are taken as whole numbers");
            f.hint = Hint{Hint::Action::give_source_format};
            findings.push_back(std::move(f));
        }
        if (p.percent)
            text += (tape.physical_start && &p == &tape.programs.front() ? "%%" : "%") +
                    (p.numbered_by_block ? "" : p.number.value_or("")) + "\n";
        for (const auto& b : p.blocks) {
            if (b.skip && !o.spec->block_skip)  // dropping the '/' would make an optional block mandatory
                findings.push_back(
                    program_finding("spec-skip", b.where, b.ordinal, "the controller format has no '/' block skip"));
            std::string line = b.skip ? "/" : "";
            auto put = [&](const Word& w) {
                if (p.numbered_by_block && w.address != 'N' && p.number && w.text == *p.number) {
                    line += (line.empty() ? "" : sep) + w.text;  // Fanuc's O1234: the program's name, kept
                    return;
                }
                if (w.macro || !w.known) {  // nothing is dropped: what cannot be written is an error
                    findings.push_back(program_finding(
                        "spec-word", w.where, b.ordinal,
                        w.text + (w.macro ? ": a macro value has no digits for the controller format"
                                          : ": not a word of the program, so not one the controller format can hold")));
                    return;
                }
                try {
                    line += (line.empty() || line == "/" ? "" : sep) + format_word(w, *o.spec, o.from, o.strip_zeros);
                } catch (const Error& e) {
                    findings.push_back(program_finding("spec-word", w.where, b.ordinal, e.what()));
                }
            };
            if (b.number) put(*b.number);
            for (const auto& w : b.words) put(w);
            for (const auto& st : b.statements)
                findings.push_back(program_finding("spec-word", st.where, b.ordinal,
                                                   "'" + st.text +
                                                       "' is a macro statement, which a controller "
                                                       "format of ГОСТ 20999-83 §9 cannot hold"));
            for (const auto& c : b.comments)
                line += (line.empty() ? "" : sep) + (c.semicolon ? ";" + c.text : "(" + c.text + ")");
            text += line + "\n";
        }
        text += p.after_end;
    }
    if (tape.record_end) text += "%\n";  // the end of record, the rewind stop, as on the tape
    return text;
}

}  // namespace tape
