// Lint against the corpus of real-shaped programs (tests/corpus/README.md): every planted mistake is
// found, and nothing else is, in the program's own dialect and in the one auto chooses.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <utility>

#include "tape/lint.hpp"
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

}  // namespace
