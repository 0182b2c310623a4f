// Lint against the corpus of real-shaped programs (tests/corpus/README.md): every planted mistake is
// found, and nothing else is, in the program's own dialect and in the one auto chooses.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include "process_util.hpp"
#include "tape/lint.hpp"
#include "tape/rules.hpp"
#include "tape/utf8_text.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

using Found = std::set<std::pair<std::string, std::uint64_t>>;  // rule, line

struct Expectation {
    Dialect dialect = Dialect::gost;
    Found findings;
};

std::string corpus_dir() { return std::string(TAPE_SOURCE_DIR) + "/tests/corpus"; }

std::vector<std::string> corpus_programs() {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(corpus_dir()))
        if (e.path().extension() == ".nc") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

Expectation expectation(const std::string& name) {
    Expectation x;
    std::istringstream in(read_text(corpus_dir() + "/" + name + ".expect"));
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        if (line.rfind("dialect:", 0) == 0) {
            std::string d = line.substr(line.find_first_not_of(' ', 8));
            x.dialect = parse_dialect(d).value();
            continue;
        }
        std::istringstream row(line);
        std::string rule;
        std::uint64_t at = 0;
        row >> rule >> at;
        x.findings.insert({rule, at});
    }
    return x;
}

// Errors and warnings: the corpus lists no notes.
Found lint_findings(const LoadedTape& t) {
    Found found;
    for (const auto& f : lint(t))
        if (f.severity != Severity::note) found.insert({std::string(f.id()), f.where.line.value_or(0)});
    return found;
}

std::string describe(const Found& f) {
    std::string s;
    for (const auto& [rule, line] : f) s += "  " + rule + " " + std::to_string(line) + "\n";
    return s.empty() ? "  (none)\n" : s;
}

class Corpus : public testing::TestWithParam<std::string> {};

TEST_P(Corpus, LintFindsThePlantedMistakesAndNothingElse) {
    Expectation want = expectation(GetParam());
    std::string text = read_text(corpus_dir() + "/" + GetParam() + ".nc");
    for (Dialect d : {want.dialect, Dialect::automatic}) {
        LoadedTape t = load(text, {}, LoadOptions{d});
        EXPECT_EQ(t.dialect, want.dialect) << "auto chose " << dialect_name(t.dialect) << ": " << t.dialect_reason;
        Found got = lint_findings(t);
        EXPECT_EQ(got, want.findings) << "--dialect " << dialect_name(d) << "\nexpected:\n"
                                      << describe(want.findings) << "found:\n"
                                      << describe(got);
    }
}

// Each block's characters are its number, words, comments and statements, and nothing else is
// dropped: the same check as tests/corpus/blocks_roundtrip.py, on the library's positions.
TEST_P(Corpus, EveryCharacterOfEveryBlockIsKept) {
    Expectation want = expectation(GetParam());
    LoadedTape t = load(read_text(corpus_dir() + "/" + GetParam() + ".nc"), {}, LoadOptions{want.dialect});
    for (const auto& p : t.programs)
        for (const auto& b : p.blocks) {
            std::string rebuilt = b.number_text();
            for (const auto& w : b.words) rebuilt += w.text;
            for (const auto& c : b.comments) rebuilt += c.text;
            for (const auto& s : b.statements) rebuilt += s.text;
            auto non_blank = [](std::string s, std::string_view drop) {
                std::erase_if(s,
                              [&](char c) { return c == ' ' || c == '\t' || c == '\r' || drop.find(c) != drop.npos; });
                std::sort(s.begin(), s.end());
                return s;
            };
            std::string source = b.source.substr(b.skip ? (b.skip_level ? 2 : 1) : 0);
            EXPECT_EQ(non_blank(source, "();"), non_blank(rebuilt, "();"))
                << "line " << b.where.line << ": " << b.source;
        }
}

INSTANTIATE_TEST_SUITE_P(Programs, Corpus, testing::ValuesIn(corpus_programs()),
                         [](const testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(CorpusSize, HoldsAtLeastThirtyPrograms) { EXPECT_GE(corpus_programs().size(), 30U); }

// The programs of ../shared/data/outside* (other people's, read where they are) against the dialect,
// listing and findings judged by hand in tests/outside_programs.expect.
struct OutsideProgram {
    Dialect dialect = Dialect::gost;
    std::uint64_t programs = 0, blocks = 0;
    Found findings;
};

std::string shared_data() { return std::string(TAPE_SOURCE_DIR) + "/../shared/data"; }

// A set of programs from outside (outside, outside2, outside3) is judged where it is present.
bool set_present(const std::string& path) {
    return std::filesystem::exists(shared_data() + "/" + path.substr(0, path.find('/')));
}

std::map<std::string, OutsideProgram> outside_expectations() {
    std::map<std::string, OutsideProgram> all;
    std::istringstream in(read_text(std::string(TAPE_SOURCE_DIR) + "/tests/outside_programs.expect"));
    OutsideProgram* current = nullptr;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        if (line.starts_with("== ")) {
            std::string mark, path, dialect;
            row >> mark >> path >> dialect;
            current = set_present(path) ? &all[path] : nullptr;
            if (!current) continue;
            current->dialect = parse_dialect(dialect).value();
            row >> current->programs >> current->blocks;
            continue;
        }
        std::string rule;
        std::uint64_t at = 0;
        row >> rule >> at;
        if (current) current->findings.insert({rule, at});
    }
    return all;
}

// Every text program under outside*/, by its path from ../shared/data.
std::vector<std::string> outside_programs() {
    std::vector<std::string> found;
    for (const auto& e : std::filesystem::recursive_directory_iterator(shared_data())) {
        std::string ext = e.path().extension().string();
        std::string relative = std::filesystem::relative(e.path(), shared_data()).string();
        // Mach3's .tap is a text program; the .tap of the tapes/ folders are tape images.
        bool tap_program = ext == ".tap" && relative.find("/tapes/") == std::string::npos;
        if (e.is_regular_file() && relative.starts_with("outside") &&
            (ext == ".nc" || ext == ".NC" || ext == ".ngc" || ext == ".gcode" || tap_program))
            found.push_back(relative);
    }
    std::sort(found.begin(), found.end());
    return found;
}

// The text as the input layer gives it (without a byte-order mark); a DOS Ctrl-Z ends it (the codec's
// concern): the program layer is judged on what comes before.
std::string program_text(const std::string& path) {
    std::string text = read_text(shared_data() + "/" + path);
    if (text.starts_with(utf8_bom)) text.erase(0, utf8_bom.size());
    if (auto z = text.find('\x1A'); z != std::string::npos) text.resize(z);
    return text;
}

class OutsideData : public testing::Test {
protected:
    void SetUp() override {
        if (!std::filesystem::exists(shared_data() + "/outside2"))
            GTEST_SKIP() << shared_data() << " is absent: the programs from outside are not in a user's clone";
    }
};

TEST_F(OutsideData, EveryProgramHasAJudgedExpectation) {
    auto expected = outside_expectations();
    std::vector<std::string> judged;
    for (const auto& [path, x] : expected) judged.push_back(path);
    EXPECT_EQ(outside_programs(), judged);
}

TEST_F(OutsideData, DialectListingAndFindingsAreAsJudged) {
    for (const auto& [path, want] : outside_expectations()) {
        LoadedTape t = load(program_text(path), {}, LoadOptions{Dialect::automatic});
        EXPECT_EQ(t.dialect, want.dialect)
            << path << ": auto chose " << dialect_name(t.dialect) << " (" << t.dialect_reason << ")";
        std::uint64_t blocks = 0;
        for (const auto& p : t.programs) blocks += p.blocks.size();
        EXPECT_EQ(t.programs.size(), want.programs) << path;
        EXPECT_EQ(blocks, want.blocks) << path;
        Found got = lint_findings(t);
        EXPECT_EQ(got, want.findings) << path << "\nexpected:\n"
                                      << describe(want.findings) << "found:\n"
                                      << describe(got);
    }
}

// The command line as a user runs it: lint exits 1 only for the errors judged real, info calls each a
// text program. (Files ending in a DOS Ctrl-Z are the codec's test: the CLI reads them through it.)
TEST_F(OutsideData, LintAndInfoOnTheCommandLine) {
    TempDir dir;
    for (const auto& [path, want] : outside_expectations()) {
        std::string file = shared_data() + "/" + path;
        if (read_text(file).find('\x1A') != std::string::npos) continue;
        bool errors = std::any_of(want.findings.begin(), want.findings.end(), [](const auto& f) {
            const Rule* r = find_rule(f.first);
            return r && r->severity == Severity::error;
        });
        Process lint({"lint", file}, dir);
        EXPECT_EQ(lint.wait(std::chrono::seconds(60)), errors ? 1 : 0) << path << ": " << lint.err();
        Process info({"info", file}, dir);
        EXPECT_EQ(info.wait(std::chrono::seconds(60)), 0) << path << ": " << info.err();
        EXPECT_NE(read_text(dir.file("stdout")).find("this is a text program"), std::string::npos) << path;
    }
}

}  // namespace
