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
        text += (tape.physical_start && &p == &tape.programs.front() ? "%%" : "%") + p.number.value_or("") + "\n";
        for (const auto& b : p.blocks) {
            if (b.skip && !o.spec->block_skip)  // dropping the '/' would make an optional block mandatory
                findings.push_back(
                    program_finding("spec-skip", b.where, b.ordinal, "the controller format has no '/' block skip"));
            std::string line = b.skip ? "/" : "";
            auto put = [&](const Word& w) {
                try {
                    line += (line.empty() || line == "/" ? "" : sep) + format_word(w, *o.spec, o.from, o.strip_zeros);
                } catch (const Error& e) {
                    findings.push_back(program_finding("spec-word", w.where, b.ordinal, e.what()));
                }
            };
            if (b.number) put(*b.number);
            for (const auto& w : b.words) put(w);
            for (const auto& c : b.comments) line += (line.empty() ? "" : sep) + "(" + c.text + ")";
            text += line + "\n";
        }
        text += p.after_end;
    }
    return text;
}

}  // namespace tape
