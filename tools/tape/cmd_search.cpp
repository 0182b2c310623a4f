// tape search: what a tape reader searches for — main blocks, the rewind stop, programs, blocks.
#include <charconv>
#include <limits>

#include "cli/messages.hpp"
#include "cli/numbers.hpp"
#include "cli/outputs.hpp"
#include "cli/programs.hpp"
#include "commands.hpp"
#include "tape/search.hpp"
#include "tape/utf8_text.hpp"

namespace cli {
namespace {

struct SearchArgs {
    std::string input = "-";
    ProgramSource source;
    std::optional<std::string> main_value;  // N, or IN when written "--main IN"
    bool rewind = false;
    std::string program;
    std::optional<long long> block;
    std::uint64_t from = 1;
};

std::string hit(const ProgramInput& in, const tape::Location& where, const std::string& what) {
    return position_text(where, in.from_tape) + (in.from_tape ? " (line " + std::to_string(where.line) + ")" : "") +
           ": " + tape::visible(what) + "\n";  // the tape's bytes: controls spelled out
}

// Block numbers have at most 9 digits on any controller; more is a typing mistake, not a block.
constexpr std::uint64_t max_block_number = 999999999;

std::optional<long long> as_number(const std::string& s) {
    long long n = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec != std::errc{} || p != s.data() + s.size()) return std::nullopt;
    return n;
}

bool looks_numeric(const std::string& s) {
    return !s.empty() && s.find_first_not_of("+-0123456789") == std::string::npos;
}

void run(SearchArgs a, const CLI::App& sub) {
    std::optional<long long> main_number;
    if (a.main_value && !a.main_value->empty()) {
        if (looks_numeric(*a.main_value)) {
            main_number = as_number(*a.main_value);
            if (!main_number || *main_number < 0 || static_cast<std::uint64_t>(*main_number) > max_block_number)
                fail("", tape::Errc::usage,
                     "--main: must be a whole number from 0 to " + std::to_string(max_block_number) + ", not '" +
                         *a.main_value + "'");
        } else if (a.input == "-") {
            a.input = *a.main_value;  // "--main IN": the option took the file
        } else {
            fail("", tape::Errc::usage, "--main takes a block number, not '" + *a.main_value + "'");
        }
    }
    // Streamed: the loader feeds the search, so a tape of any length is searched in bounded memory.
    ProgramInput in = open_program(a.input, a.source);
    using Kind = tape::SearchQuery::Kind;
    tape::SearchQuery q;
    q.from = a.from;
    q.from_tape = in.from_tape;
    if (sub.count("--main")) {
        q.kind = Kind::main_block;
        q.number = main_number;
    } else if (a.rewind) {
        q.kind = Kind::rewind_stop;
    } else if (!a.program.empty()) {
        q.kind = Kind::program;
        q.program = a.program;
    } else if (a.block) {
        q.kind = Kind::numbered_block;
        q.number = a.block;
    } else {
        return;
    }
    tape::Searcher searcher(q);
    load_program(in, searcher);
    std::string out;
    for (const auto& h : searcher.hits()) out += hit(in, h.where, h.text);
    std::string where = std::string(in.from_tape ? "frame " : "line ") + std::to_string(a.from);
    if (out.empty() && in.damaged) end_program(in);
    if (out.empty()) {
        std::string what = q.kind == Kind::main_block
                               ? std::string("no main block") +
                                     (main_number ? " :" + std::to_string(*main_number) : "") + " from " + where
                           : q.kind == Kind::rewind_stop ? "no '%' before " + where
                           : q.kind == Kind::program     ? "no program " + a.program
                                                         : "no block numbered " + std::to_string(*a.block);
        fail(in.name, tape::Errc::not_in_code, what);
    }
    write_output("-", out, false, false);
    end_program(in);
}

}  // namespace

void add_search(CLI::App& app) {
    auto a = std::make_shared<SearchArgs>();
    auto* sub =
        app.add_subcommand("search", "Find main blocks, the rewind stop, a program or a block, with their frames");
    sub->add_option("input", a->input, "Tape image or text program; - or nothing for stdin");
    auto* main =
        sub->add_option("--main", a->main_value, "Main blocks (':') from --from on, or only the one numbered N")
            ->expected(0, 1);
    auto* rewind = sub->add_flag("--rewind", a->rewind, "The '%' a rewinding reader stops at, before --from");
    auto* program = sub->add_option("--program", a->program, "The program numbered N (after '%')");
    auto* block = sub->add_option("--block", a->block, "Blocks numbered N (N or ':' word)")
                      ->check(whole_number(0, max_block_number));
    main->excludes(rewind)->excludes(program)->excludes(block);
    rewind->excludes(program)->excludes(block);
    program->excludes(block);
    sub->add_option("--from", a->from, "Frame (line, for text) to search from; default the start")
        ->check(whole_number(1, std::numeric_limits<std::int64_t>::max()))
        ->capture_default_str();
    add_program_source_options(sub, a->source, true);
    sub->callback([a, sub] {
        if (!sub->count("--main") && !a->rewind && a->program.empty() && !a->block)
            throw CLI::RequiredError("one of --main, --rewind, --program, --block");
        run(*a, *sub);
    });
}

}  // namespace cli
