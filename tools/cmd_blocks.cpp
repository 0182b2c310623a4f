// tape blocks: the programs on a tape, one line per block (кадр), or JSON for other programs.
#include <sstream>

#include "cli_common.hpp"
#include "commands.hpp"
#include "tape/functions.hpp"

namespace cli {
namespace {

struct BlocksArgs {
    std::string input = "-";
    ProgramSource source;
    bool json = false, explain = false;
    std::string lang = "en";
};

std::string optional_number(const std::optional<std::uint64_t>& n) { return n ? std::to_string(*n) : "null"; }

std::string explanation(const tape::Block& b, bool russian) {
    std::string out;
    for (const auto& w : b.words) {
        if (w.address != 'G' && w.address != 'M') continue;
        auto v = w.integer();
        const tape::NcFunction* f = v ? tape::find_nc_function(w.address, *v) : nullptr;
        if (!f) continue;
        out += (out.empty() ? "" : ", ") + w.text + " " + std::string(russian ? f->ru : f->en);
    }
    return out;
}

std::string findings_json(const std::vector<tape::Finding>& findings) {
    std::string out = "[";
    for (const auto& f : findings) {
        out += std::string(out.size() > 1 ? ", " : "") + "{\"rule\": " + json_string(std::string(f.rule)) +
               ", \"severity\": " + json_string(std::string(tape::severity_name(f.severity))) +
               ", \"frame\": " + optional_number(f.where.frame) + ", \"line\": " + std::to_string(f.where.line) +
               ", \"column\": " + std::to_string(f.where.column) + ", \"block\": " + std::to_string(f.block) +
               ", \"message\": " + json_string(f.message) + "}";
    }
    return out + "]";
}

std::string as_json(const tape::LoadedTape& t) {
    std::ostringstream out;
    out << "{\"programs\": [";
    for (std::size_t i = 0; i < t.programs.size(); ++i) {
        const auto& p = t.programs[i];
        out << (i ? ", " : "") << "{\"number\": " << (p.number ? json_string(*p.number) : "null")
            << ", \"first_frame\": " << optional_number(p.start.frame) << ", \"line\": " << p.start.line
            << ", \"ended\": " << (p.ended ? "true" : "false") << ", \"blocks\": [";
        for (std::size_t k = 0; k < p.blocks.size(); ++k) {
            const auto& b = p.blocks[k];
            out << (k ? ", " : "") << "{\"frame\": " << optional_number(b.where.frame) << ", \"line\": " << b.where.line
                << ", \"number\": " << (b.number ? json_string(b.number->text) : "null") << ", \"main\": " << (b.main ? "true" : "false")
                << ", \"skip\": " << (b.skip ? "true" : "false") << ", \"words\": [";
            for (std::size_t w = 0; w < b.words.size(); ++w) out << (w ? ", " : "") << json_string(b.words[w].text);
            out << "], \"comments\": [";
            for (std::size_t c = 0; c < b.comments.size(); ++c) out << (c ? ", " : "") << json_string(b.comments[c].text);
            out << "]}";
        }
        out << "], \"after_end\": " << json_string(p.after_end) << "}";
    }
    out << "], \"label\": " << json_string(t.label) << ", \"physical_start\": " << (t.physical_start ? "true" : "false")
        << ", \"diagnostics\": " << findings_json(t.findings) << "}\n";
    return out.str();
}

std::string as_listing(const tape::LoadedTape& t, bool from_tape, bool explain, bool russian) {
    std::ostringstream out;
    if (t.label.find_first_not_of(" \t\r\n") != std::string::npos) out << "label: " << t.label << (t.label.back() == '\n' ? "" : "\n");
    if (t.physical_start) out << "%% physical start of the tape\n";
    for (const auto& p : t.programs) {
        out << "program " << (p.number ? *p.number : "(no number)") << " at " << position_text(p.start, from_tape) << "\n";
        for (const auto& b : p.blocks) {
            std::string pos = position_text(b.where, from_tape);
            out << "  " << pos << std::string(pos.size() < 12 ? 12 - pos.size() : 1, ' ') << b.text();
            if (explain) {
                std::string e = explanation(b, russian);
                if (!e.empty()) out << "    ; " << e;
            }
            out << "\n";
        }
        out << (p.ended ? "  end of program\n" : "  no end (M02/M30)\n");
        if (p.after_end.find_first_not_of(" \t\r\n") != std::string::npos)
            out << "after the end, not part of the program:\n" << p.after_end << (p.after_end.back() == '\n' ? "" : "\n");
    }
    return out.str();
}

void run(const BlocksArgs& a) {
    ProgramInput in = load_program(a.input, a.source);
    for (const auto& f : in.tape.findings)
        say(in.name, position_text(f.where, in.from_tape) + ": " + std::string(tape::severity_name(f.severity)) + ": " + f.message);
    write_output("-", a.json ? as_json(in.tape) : as_listing(in.tape, in.from_tape, a.explain, a.lang == "ru"), false, false);
}

}  // namespace

void add_blocks(CLI::App& app) {
    auto a = std::make_shared<BlocksArgs>();
    auto* sub = app.add_subcommand("blocks", "List the programs and blocks (кадры) on a tape or in a text program");
    sub->add_option("input", a->input, "Tape image or text program; - or nothing for stdin");
    add_program_source_options(sub, a->source);
    sub->add_flag("--json", a->json, "JSON for other programs (schema in tape(1))");
    sub->add_flag("--explain", a->explain, "Name the G and M functions of each block (ГОСТ 20999-83 tables 4-8)");
    sub->add_option("--lang", a->lang, "Language of --explain: en or ru")->check(CLI::IsMember({"en", "ru"}))->capture_default_str();
    sub->callback([a] { run(*a); });
}

}  // namespace cli
