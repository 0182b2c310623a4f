#include "tape/reformat.hpp"

#include <optional>

#include "tape/lint.hpp"
#include "tape/machine_checks.hpp"

namespace tape {
namespace {

// A word in millimetres for an axis the machine counts in pulses: writing its digits would move the
// axis by that many pulses, not millimetres.
bool millimetres_for_pulses(const MachineProfile* m, const Word& w) {
    const MachineAxis* a = m && w.has_point() ? m->find_axis(w.address) : nullptr;
    return a && a->mm_per_pulse > 0;
}

// A word as the controller format writes it, or nullopt with a finding where it cannot be written (nothing
// is dropped unsaid). name: Fanuc's O1234 block, the program's name, kept as written.
struct WrittenWord {
    std::string text;
    bool name = false;
};
std::optional<WrittenWord> written_word(const Word& w, const Block& b, const Program& p, const FormatSpec& spec,
                                        const ReformatOptions& o, std::vector<Diagnostic>& findings) {
    if (p.numbered_by_block && w.address != 'N' && p.number && w.text == *p.number) return WrittenWord{w.text, true};
    if (w.macro || !w.known) {
        findings.push_back(program_finding(
            "spec-word", w.where, b.ordinal,
            w.text + (w.macro ? ": a macro value has no digits for the controller format"
                              : ": not a word of the program, so not one the controller format can hold")));
        return std::nullopt;
    }
    if (millimetres_for_pulses(o.machine, w)) {
        findings.push_back(program_finding("spec-word", w.where, b.ordinal,
                                           w.text + ": " + o.machine->title + " counts " + std::string(1, w.address) +
                                               " in pulses; converting millimetres to pulses is not done"));
        return std::nullopt;
    }
    try {
        return WrittenWord{format_word(w, spec, o.from, o.strip_zeros)};
    } catch (const Error& e) {
        findings.push_back(program_finding("spec-word", w.where, b.ordinal, e.what()));
        return std::nullopt;
    }
}

}  // namespace

std::string reformat(const LoadedTape& tape, const ReformatOptions& o, std::vector<Diagnostic>& findings) {
    if (!o.spec && !o.machine) throw Error(Errc::usage, "no controller format to write the program for");
    std::optional<MachineFormat> machine;
    if (o.machine) machine.emplace(*o.machine);
    const std::string sep = o.spaces ? " " : "";
    std::string text = tape.label;
    for (const auto& p : tape.programs) {
        if (machine) machine->program_start();
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
            const FormatSpec& spec = machine ? machine->block(b) : *o.spec;
            if (b.skip && !spec.block_skip)  // dropping the '/' would make an optional block mandatory
                findings.push_back(
                    program_finding("spec-skip", b.where, b.ordinal, "the controller format has no '/' block skip"));
            std::string line = b.skip ? "/" : "";
            auto put = [&](const Word& w) {
                if (auto t = written_word(w, b, p, spec, o, findings))
                    line += (line.empty() || (line == "/" && !t->name) ? "" : sep) + t->text;
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
