// tape blocks: the programs on a tape, one line per block (кадр), or JSON for other programs.

#include "cli/globals.hpp"
#include "cli/json.hpp"
#include "cli/machines.hpp"
#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/outputs.hpp"
#include "cli/programs.hpp"
#include "commands.hpp"
#include "motion_stats_report.hpp"
#include "tape/code_tables.hpp"
#include "tape/machine_checks.hpp"
#include "tape/utf8_text.hpp"

namespace cli {
namespace {

struct BlocksArgs {
    std::string input = "-";
    ProgramSource source;
    bool json = false, explain = false, strict = false, stats = false;
    std::string lang = "en", machine;
    std::optional<tape::MachineProfile> profile{};  // --machine, loaded before the listing starts
    MotionArgs motion;
    StatsArgs stats_args;
};

std::string statement_kind(tape::Statement::Kind k) {
    using K = tape::Statement::Kind;
    switch (k) {
        case K::assignment:
            return "assignment";
        case K::if_goto:
            return "if-goto";
        case K::if_then:
            return "if-then";
        case K::go_to:
            return "goto";
        case K::while_do:
            return "while-do";
        case K::loop_do:
            return "do";
        case K::loop_end:
            return "end";
        case K::output:
            return "output";
        case K::o_word:
            return "o-word";
    }
    return "";
}

std::string location_json(const tape::Location& l) {
    return "{\"frame\": " + json_number(l.frame) + ", \"line\": " + std::to_string(l.line) + "}";
}

// One block for --json: where it is, its source and what the loader made of it.
Json block_value(const tape::Block& b) {
    Json words = Json::array(), flagged = Json::array(), comments = Json::array(), statements = Json::array();
    for (const auto& w : b.words) {
        words.push_back(w.text);
        if (!w.known) flagged.push_back(w.text);
    }
    for (const auto& c : b.comments) comments.push_back(c.text);
    for (const auto& st : b.statements)
        statements.push_back(Json{{"kind", statement_kind(st.kind)}, {"text", st.text}});
    return Json{{"frame", b.where.frame ? Json(*b.where.frame) : Json(nullptr)},
                {"line", b.where.line},
                {"column", b.where.column},
                {"source", b.source},
                {"number", b.number ? Json(b.number->text) : Json(nullptr)},
                {"main", b.main},
                {"skip", b.skip},
                {"skip_level", b.skip_level},
                {"ends_program", b.ends},
                {"words", words},
                {"flagged", flagged},
                {"comments", comments},
                {"statements", statements}};
}

// Blocks are written as the loader gives them, so that a tape of any length lists in bounded memory:
// only the label, the text after a program's end and the findings are held.
class Lister : public tape::ProgramVisitor {
public:
    Lister(const BlocksArgs& a, const std::string& name, bool from_tape, std::optional<tape::LeaderLabel> leader)
        : a_(a), name_(name), from_tape_(from_tape), leader_(std::move(leader)) {
        if (a_.json) out_ += "{\"programs\": [";
        if (!a_.json && leader_) out_ += "leader label: " + label_text(*leader_) + "\n";
    }

    void label(std::string_view text) override { label_ += text; }
    void physical_start() override {
        physical_start_ = true;
        flush_label();
        if (!a_.json) out_ += "%% physical start of the tape\n";
    }
    void program_start(const tape::Program& p) override {
        close_program();
        machine_ = {};
        flush_label();
        in_program_ = true;
        ended_ = false;
        blocks_ = 0;
        if (a_.json)
            out_ += std::string(programs_ ? ", " : "") +
                    "{\"number\": " + (p.number ? json_string(*p.number) : "null") +
                    ", \"first_frame\": " + json_number(p.start.frame) + ", \"line\": " + std::to_string(p.start.line) +
                    ", \"blocks\": [";
        else
            out_ += "program " + (p.number ? tape::visible(*p.number) : "(no number)") + " at " +
                    position_text(p.start, from_tape_) + "\n";
        ++programs_;
    }
    void block(const tape::Block& b) override {
        if (b.ends_program()) ended_ = true;
        if (a_.json) {
            out_ += std::string(blocks_ ? ", " : "") + json_text(block_value(b));
        } else {
            std::string pos = position_text(b.where, from_tape_);
            out_ += "  " + pos + std::string(pos.size() < 12 ? 12 - pos.size() : 1, ' ') + tape::visible(b.text());
            std::string flagged;
            for (const auto& w : b.words)
                if (!w.known) flagged += (flagged.empty() ? "" : " ") + tape::visible(w.text);
            if (!flagged.empty()) out_ += "    ! not read: " + flagged;
            if (a_.explain) {
                machine_.block(b);
                std::string e = a_.profile ? tape::explain_machine_codes(b, *a_.profile, a_.lang == "ru")
                                           : tape::explain_codes(b, dialect_, machine_.machine(), a_.lang == "ru");
                if (!e.empty()) out_ += "    ; " + e;
            }
            out_ += "\n";
        }
        ++blocks_;
        if (out_.size() >= 64 << 10) flush();
    }
    void after_end(std::string_view text, const tape::Location&) override {
        (in_program_ ? after_end_ : after_record_) += text;  // after the end of record, nothing is read
    }
    void dialect(const tape::DialectChoice& choice) override {
        dialect_ = choice.dialect;
        if (globals().verbosity == 0 && choice.dialect == tape::Dialect::none)  // -v says why, -q nothing
            say(name_,
                "no known dialect fits: the blocks are listed as written, and only what holds for every "
                "control is checked (-v says why)");
        if (globals().verbosity == 0 && choice.close)
            say(name_, "read as " + std::string(tape::dialect_name(choice.dialect)) + ", close to " +
                           std::string(tape::dialect_name(*choice.close)) +
                           ": only what both readings find is reported (-v says why)");
    }
    void record_end(const tape::Location& where, bool closes_program) override {
        if (closes_program) ended_ = true;
        close_program();
        record_end_ = where;
        if (!a_.json) out_ += "% end of record (rewind stop) at " + position_text(where, from_tape_) + "\n";
    }
    void finding(const tape::Finding& f) override {
        tape::Finding shown = f;
        if (f.code == tape::Errc::blank_frame && a_.strict) {  // --strict: a blank in a block is damage
            shown.severity = tape::Severity::error;
            blank_in_block_ = true;
        }
        say(name_, position_text(shown.where, from_tape_) + ": " + std::string(tape::severity_name(shown.severity)) +
                       ": " + tape::visible(shown.message));
        if (a_.json) findings_ += std::string(findings_.empty() ? "" : ", ") + finding_json(shown);
    }
    bool blank_in_block() const { return blank_in_block_; }

    void finish() {
        close_program();
        flush_label();
        if (!a_.json && has_text(after_record_)) out_ += "after the end of record, not read:\n" + shown(after_record_);
        if (a_.json)
            out_ += "], \"dialect\": " + json_string(std::string(tape::dialect_name(dialect_))) +
                    ", \"record_end\": " + (record_end_ ? location_json(*record_end_) : "null") +
                    ", \"after_record_end\": " + json_string(after_record_) + ", \"label\": " + json_string(label_) +
                    ", \"leader_label\": " + label_json(leader_) +
                    ", \"physical_start\": " + (physical_start_ ? "true" : "false") + ", \"diagnostics\": [" +
                    findings_ + "]}\n";
        flush();
    }

private:
    void flush() {
        write_output("-", out_, false, false);
        out_.clear();
    }
    void flush_label() {
        if (a_.json || label_done_) return;
        label_done_ = true;
        if (has_text(label_)) out_ += "label: " + shown(label_);
    }
    // Text that is more than blanks and reader on/off controls (DC1-DC4).
    static bool has_text(const std::string& s) {
        return s.find_first_not_of(" \t\r\n\x11\x12\x13\x14") != std::string::npos;
    }
    // Lines of text from the tape as the terminal should show them: controls by name, one LF at the end.
    static std::string shown(const std::string& s) {
        std::string out;
        std::size_t b = 0;
        while (b < s.size()) {
            std::size_t e = std::min(s.find('\n', b), s.size());
            std::string_view line(s.data() + b, e - b);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            out += tape::visible(line) + "\n";
            b = e + 1;
        }
        return out;
    }
    void close_program() {
        if (!in_program_) return;
        in_program_ = false;
        if (a_.json) {
            out_ += std::string("], \"ended\": ") + (ended_ ? "true" : "false") +
                    ", \"after_end\": " + json_string(after_end_) + "}";
        } else {
            out_ += ended_ ? "  end of program\n" : "  no end (M02/M30)\n";
            if (has_text(after_end_)) out_ += "after the end, not part of the program:\n" + shown(after_end_);
        }
        after_end_.clear();
    }

    const BlocksArgs& a_;
    const std::string& name_;
    bool from_tape_;
    std::string out_, label_, after_end_, after_record_, findings_;
    tape::Dialect dialect_ = tape::Dialect::gost;
    tape::MachineEvidence machine_;  // --explain: the program's machine, for the codes that differ
    std::optional<tape::Location> record_end_;
    std::optional<tape::LeaderLabel> leader_;  // letters of holes in the leader, not read as text
    bool label_done_ = false, physical_start_ = false, in_program_ = false, ended_ = false, blank_in_block_ = false;
    std::uint64_t programs_ = 0, blocks_ = 0;
};

void run(BlocksArgs& a) {
    a.motion.machine = a.machine;  // --machine: for --stats, the lathe, formats and rapid rates
    if (a.stats) return run_motion_stats(a.input, a.source, a.motion, StatsArgs{a.stats_args.rapid_mm_per_min, a.json});
    a.profile = machine_or_fail(a.machine);
    ProgramInput in = open_program(a.input, a.source);
    if (a.profile && a.source.dialect == "auto") in.load.dialect = a.profile->dialect;
    std::optional<tape::LeaderLabel> leader;
    try {
        if (in.from_tape) leader = in.input->label();
    } catch (const tape::Error& e) {
        fail(in.name, e);
    }
    Lister lister(a, in.name, in.from_tape, leader);
    load_program(in, lister);
    lister.finish();
    end_program(in);
    if (lister.blank_in_block()) throw Exit{bad_data};
}

}  // namespace

void add_blocks(CLI::App& app) {
    auto a = std::make_shared<BlocksArgs>();
    auto* sub = app.add_subcommand("blocks", "List the programs and blocks (кадры) on a tape or in a text program");
    sub->add_option("input", a->input, "Tape image or text program; - or nothing for stdin");
    add_program_source_options(sub, a->source, true);
    sub->add_flag("--json", a->json, "JSON for other programs (schema in tape(1))");
    sub->add_flag("--explain", a->explain,
                  "Name the G and M functions of each block as the dialect's table does (ГОСТ 20999-83 tables 4-8, "
                  "Fanuc lathe or mill, LinuxCNC)");
    add_machine_option(sub, a->machine, "--explain names its G and M codes, feed, speed and tool words");
    sub->add_flag("--strict", a->strict, "Blank tape inside a block is an error: exit 1");
    auto* stats = sub->add_flag("--stats", a->stats,
                                "Instead of the blocks, the figures of the toolpath per tool: the least and most of "
                                "each axis, cutting and rapid length, and time at the programmed feeds");
    sub->add_option("--rapid", a->stats_args.rapid_mm_per_min, "With --stats: the machine's rapid rate, mm/min")
        ->check(real_number(1, 1e6))
        ->needs(stats);
    add_motion_options(sub, a->motion, false);
    sub->add_option("--lang", a->lang, "Language of --explain: en or ru")
        ->check(CLI::IsMember({"en", "ru"}))
        ->capture_default_str();
    sub->callback([a] { run(*a); });
}

}  // namespace cli
