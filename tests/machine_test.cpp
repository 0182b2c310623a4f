// Machine profiles: the strict reader's errors (file, line, key), every bundled profile, and what lint
// and blocks --explain make of the sample tapes with the 16К20Ф3С5's profile.
#include "tape/machine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "tape/decode.hpp"
#include "tape/file_io.hpp"
#include "tape/lint.hpp"
#include "tape/machine_checks.hpp"
#include "test_util.hpp"

using namespace tape;

namespace {

const std::string minimal = "name = \"m\"\nkind = \"mill\"\nsource = \"test\"\n";

// The message of the error reading text throws, or "" when it reads.
std::string error_of(const std::string& text) {
    try {
        parse_machine_profile(text, "m.toml");
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage);
        return e.what();
    }
    return "";
}

std::vector<Finding> lint_sample(const std::string& name, const MachineProfile& m) {
    auto bytes = read_file(sample_path(name));
    Code code = name.find(".eia.") != std::string::npos ? Code::eia : Code::iso;
    auto r = decode(bytes, DecodeOptions{.code = code, .positions = true});
    LoadedTape t = load(r.text, r.frame_of, LoadOptions{m.dialect});
    return lint(t, LintOptions{.machine = &m});
}

std::vector<std::string> messages_of(const std::vector<Finding>& all, std::string_view rule) {
    std::vector<std::string> out;
    for (const auto& f : all)
        if (f.rule == rule) out.push_back(f.message);
    return out;
}

}  // namespace

TEST(MachineProfile, MinimalReads) {
    MachineProfile p = parse_machine_profile(minimal, "m.toml");
    EXPECT_EQ(p.name, "m");
    EXPECT_EQ(p.kind, MachineKind::mill);
    EXPECT_EQ(p.sources.at("kind"), "test");
}

TEST(MachineProfile, ErrorsNameFileLineAndKey) {
    EXPECT_EQ(error_of(minimal + "colour = \"red\"\n"),
              "m.toml: line 4: colour: unknown key (known here: source, name, title, aliases, kind, "
              "diameter_programming, dialect, format, code, feed, speed, axis, arc, line)");
    EXPECT_EQ(error_of(minimal + "[format]\nspec = \"N3 X+6\"\n"),
              "m.toml: line 5: format.spec: format specification 'N3 X+6': X+6: a dimension word takes two digits "
              "(before and after the point), or three with a leading 0 (leading zeros omitted) or a trailing 0 "
              "(trailing zeros omitted)");
    EXPECT_EQ(
        error_of(minimal + "[[code]]\ncode = \"G10\"\nmeaning = \"a\"\n[[code]]\ncode = \"G10\"\nmeaning = \"b\"\n"),
        "m.toml: line 8: code[2].code: G10 is given twice (first on line 4)");
    EXPECT_EQ(error_of(minimal + "[arc]\ntolerance_mm = \"small\"\n"),
              "m.toml: line 5: arc.tolerance_mm: must be a number from 0 to 10, not \"small\"");
    EXPECT_EQ(error_of(minimal + "[line]\nbaud = 9600\nflow = \"xon\"\n"),
              "m.toml: line 6: line.flow: must be one of xonxoff, rtscts, none, not \"xon\"");
    EXPECT_EQ(error_of("name = \"m\"\nkind = \"mill\"\n"),
              "m.toml: line 1: source: is required: where the profile's values come from");
    EXPECT_EQ(error_of(minimal + "[[code]]\ncode = \"G10\"\nmeaning = \"a\"\nmode = \"long\"\n"),
              "m.toml: line 7: code[1].mode: no [[format.mode]] is named \"long\"");
    EXPECT_EQ(
        error_of(minimal + "[feed]\n[[feed.code]]\nfirst_digit = 1\nmeaning = \"a\"\n[[feed.code]]\nfirst_digit = 1\n"
                           "meaning = \"b\"\n"),
        "m.toml: line 9: feed.code[2].first_digit: 1 is given twice");
    EXPECT_EQ(error_of(minimal + "kind2 = { value = 1, source = \"x\", extra = 2 }\n"),
              "m.toml: line 4: kind2: unknown key (known here: source, name, title, aliases, kind, "
              "diameter_programming, dialect, format, code, feed, speed, axis, arc, line)");
    EXPECT_EQ(error_of(minimal + "title = { value = \"t\", src = \"x\" }\n"),
              "m.toml: line 4: title.src: unknown key (known here: source, value)");
}

TEST(MachineProfile, TomlSyntaxErrorNamesTheLine) {
    std::string e = error_of(minimal + "kind = \"lathe\"\n");
    EXPECT_EQ(e.rfind("m.toml: line 4: ", 0), 0U) << e;
}

TEST(MachineProfile, BareNonAsciiIsRefusedBeforeParsing) {
    EXPECT_EQ(error_of(minimal + "t\xC3\xA9 = 1\n").rfind("m.toml: line 4: 'é' outside quotes", 0), 0U);
    EXPECT_EQ(error_of(minimal + "title = \"Н22\" # Н22-1М\n"), "");
}

TEST(MachineProfile, EveryBundledProfileReads) {
    auto bundled = bundled_machines();
    ASSERT_GE(bundled.size(), 9U);
    for (const auto& b : bundled) {
        SCOPED_TRACE(std::string(b.name));
        MachineProfile p = parse_machine_profile(b.text, std::string(b.name) + ".toml");
        EXPECT_EQ(p.name, b.name);  // the file is named after the profile
        EXPECT_FALSE(p.sources.at("machine").empty());
        for (const auto& c : p.codes) EXPECT_FALSE(c.source.empty()) << c.code;
        EXPECT_EQ(load_machine(p.name).name, p.name);
        for (const auto& a : p.aliases) EXPECT_EQ(load_machine(a).name, p.name) << a;
    }
}

TEST(MachineProfile, The16K20F3S5FromTheCourseText) {
    MachineProfile p = load_machine("16К20Ф3С5");
    EXPECT_EQ(p.kind, MachineKind::lathe);
    EXPECT_EQ(p.rapid_mm_per_min.at('Z'), 4800);
    EXPECT_EQ(p.rapid_mm_per_min.at('X'), 2400);
    EXPECT_EQ(p.find_axis('X')->mm_per_pulse, 0.005);
    ASSERT_TRUE(p.find_code('G', 10));
    EXPECT_EQ(p.find_mode(p.find_code('G', 10)->mode)->digits, 6);
    EXPECT_EQ(p.find_mode(p.find_code('G', 11)->mode)->digits, 4);
    EXPECT_EQ(p.find_mode(p.initial_mode)->digits, 5);
    EXPECT_TRUE(p.find_feed_code(7));
    EXPECT_FALSE(p.find_feed_code(3));
    EXPECT_EQ(p.find_speed_code(47)->rpm, 1000);
    EXPECT_FALSE(p.speed_table_complete);
}

TEST(MachineProfile, UserProfilesByPathAndFolder) {
    TempDir dir;
    std::ofstream(dir.file("mine.toml")) << minimal;
    EXPECT_EQ(load_machine(dir.file("mine.toml")).name, "m");
    std::filesystem::create_directories(dir.path + "/tape/machines");
    std::ofstream(dir.path + "/tape/machines/shop.toml") << minimal;
    std::ofstream(dir.path + "/tape/machines/broken.toml") << "name = 1\n";
    ::setenv("XDG_CONFIG_HOME", dir.path.c_str(), 1);
    EXPECT_EQ(load_machine("shop").name, "m");
    auto all = list_machines();
    ::unsetenv("XDG_CONFIG_HOME");
    auto broken = std::find_if(all.begin(), all.end(), [](const MachineListing& m) { return m.name == "broken"; });
    ASSERT_NE(broken, all.end());
    EXPECT_TRUE(broken->broken);
    EXPECT_THROW(load_machine("no-such-machine"), Error);
}

TEST(MachineLint, SampleTapeFindingsWithTheProfile) {
    MachineProfile p = load_machine("16k20f3s5");
    for (std::string tape : {"16k20f3s5-turning.iso.ptp", "16k20f3s5-turning.eia.ptp"}) {
        SCOPED_TRACE(tape);
        auto findings = lint_sample(tape, p);
        auto digits = messages_of(findings, "spec-digits");
        // What the course text's OCR printed off the Н22-1М's format (data/machines/16k20f3s5.toml).
        ASSERT_EQ(digits.size(), 5U);
        EXPECT_EQ(digits[0], "F2000: F5 takes exactly 5 digit(s)");
        EXPECT_EQ(digits[1], "S64: S3 takes exactly 3 digit(s)");
        EXPECT_EQ(digits[2],
                  "X+0000000: X+50 takes exactly 5 digits (5 before the implied point, 0 after) (from the program's "
                  "start: normal dimensions, 5 digits)");
        EXPECT_EQ(digits[4],
                  "X-0040000: X+60 takes exactly 6 digits (6 before the implied point, 0 after) (G10 in effect: long "
                  "dimensions, 6 digits)");
        EXPECT_TRUE(messages_of(findings, "machine-feed-code").empty());
        // Without the profile the sample lints clean.
        auto bytes = read_file(sample_path(tape));
        Code code = tape.find(".eia.") != std::string::npos ? Code::eia : Code::iso;
        auto r = decode(bytes, DecodeOptions{.code = code, .positions = true});
        EXPECT_TRUE(lint(load(r.text, r.frame_of)).empty());
    }
}

TEST(MachineLint, LongModeDigitsAndFeedTable) {
    MachineProfile p = load_machine("16k20f3s5");
    auto findings = lint(load("%\nN001 G10 X+12345 F10600\nN002 Z+000500 F30600\nN003 G01 X+12345 F70000\nN004 M102\n"),
                         LintOptions{.machine = &p});
    auto digits = messages_of(findings, "spec-digits");
    ASSERT_EQ(digits.size(), 1U);
    EXPECT_EQ(digits[0],
              "X+12345: X+60 takes exactly 6 digits (6 before the implied point, 0 after) (G10 in effect: long "
              "dimensions, 6 digits)");
    auto feeds = messages_of(findings, "machine-feed-code");
    ASSERT_EQ(feeds.size(), 1U);
    EXPECT_EQ(feeds[0],
              "F30600: the first digit 3 is no mode of 16К20Ф3С5 lathe, Н22-1М control's feed code table "
              "(1, 2, 7; Smolin 1991, table 3 (ПОЯСНЕНИЕ К СЛОВУ «ПОДАЧА»))");
    auto prefix = lint(load("%\nN001 G01 X+00100 F10600 M204\nN002 M102\n"), LintOptions{.machine = &p});
    EXPECT_EQ(messages_of(prefix, "machine-prefix").size(), 1U);
}

TEST(MachineExplain, EveryCodeOfTheSampleIsNamed) {
    MachineProfile p = load_machine("16k20f3s5");
    auto bytes = read_file(sample_path("16k20f3s5-turning.iso.ptp"));
    auto r = decode(bytes, DecodeOptions{.positions = true});
    LoadedTape t = load(r.text, r.frame_of);
    ASSERT_EQ(t.programs.size(), 1U);
    for (const auto& b : t.programs[0].blocks) {
        std::string e = explain_machine_codes(b, p, false);
        for (const auto& w : b.words) {
            if (std::string_view("GMFST").find(w.address) == std::string_view::npos) continue;
            EXPECT_NE(e.find(w.text), std::string::npos) << w.text << " in " << e;
        }
    }
    const auto& n1 = t.programs[0].blocks[0];
    EXPECT_EQ(explain_machine_codes(n1, p, false),
              "G27 absolute dimensions (absolute coordinate system), F2000: 4 digit(s) where F5 takes 5: not read, "
              "S64: 2 digit(s) where S3 takes 3: not read, T102 tool 2, after the machine's acknowledgement, M104 "
              "spindle counter-clockwise, after the machine's acknowledgement");
}

// The profile's line fills the keys a serial: string does not give, read as the serial backend reads
// them: a key given (even %XX-encoded) wins, parity follows the bits in force, and a string the port
// would refuse is refused here with the same usage error. Other devices are left as they are.
TEST(MachineLine, FillsTheKeysTheDeviceStringDoesNotGive) {
    tape::MachineLine l;
    l.baud = 4800;
    l.data_bits = 7;
    l.stop_bits = 2;
    l.flow = tape::Flow::none;
    l.parity = tape::Parity::even;
    EXPECT_EQ(tape::device_with_machine_line("serial:/dev/ttyS0", l),
              "serial:/dev/ttyS0?baud=4800&bits=7&stop=2&flow=none&parity=even");
    EXPECT_EQ(tape::device_with_machine_line("serial:/dev/ttyS0?baud=9600&bits=%38", l),
              "serial:/dev/ttyS0?baud=9600&bits=%38&stop=2&flow=none");  // 8 bits: no parity bit added
    EXPECT_EQ(tape::device_with_machine_line("file:out.ptp", l), "file:out.ptp");
    try {
        tape::device_with_machine_line("serial:/dev/ttyS0?speed=9600", l);
        FAIL() << "an unknown setting was taken";
    } catch (const tape::Error& e) {
        EXPECT_EQ(e.code(), tape::Errc::usage);
        EXPECT_NE(std::string(e.what()).find("unknown setting 'speed'"), std::string::npos) << e.what();
    }
}
