// The guard run before toml++ parses a file: a non-ASCII character outside strings and comments is
// refused with its line (toml++ 3.3.0 reaches __builtin_unreachable on it), anywhere else it passes.
#include "common/toml_guard.hpp"

#include <gtest/gtest.h>

#include "tape/error.hpp"

namespace {

// The error the guard throws for text, or nullopt when it passes.
std::optional<tape::Error> refused(std::string_view text) {
    try {
        tape::reject_bare_non_ascii(text, "dnc.toml");
    } catch (const tape::Error& e) {
        return e;
    }
    return std::nullopt;
}

TEST(TomlGuard, BareNonAsciiNamedWithFileLineAndCharacter) {
    auto e = refused("[[machine]]\n# Фрезер in a comment\nname = Фрезер\n");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code(), tape::Errc::usage);
    EXPECT_EQ(e->where().line, 3u);
    EXPECT_EQ(e->where().column, 8u);
    std::string message = e->what();
    EXPECT_NE(message.find("dnc.toml"), std::string::npos) << message;
    EXPECT_NE(message.find("'Ф'"), std::string::npos) << message;
}

TEST(TomlGuard, TextInStringsAndCommentsPasses) {
    const char* fine[] = {
        "name = \"Фрезер\"\n",
        "name = 'Фрезер' # станок\n",
        "\"ключ\" = 1\n",
        "'ключ' = 1\n",
        "note = \"\"\"\nстрока\n\"кавычки\" \"\" внутри\n\"\"\"\n",
        "note = '''\nстрока ' и '' внутри\n'''\n",
        "note = \"a \\\" Ж\"\n",                   // an escaped quote does not end the string
        "note = \"\"\"a \\\"\"\" Ж\"\"\"\n",       // nor in a multi-line one
        "note = \"\"\"кавычка в конце\"\"\"\"\n",  // four quotes: the string ends with one
        "a = 1\r\n# Ж\r\nb = \"Ж\"\r\n",
        "",
    };
    for (const char* text : fine) EXPECT_FALSE(refused(text)) << text;
}

TEST(TomlGuard, StringsEndWhereTomlEndsThem) {
    // An escaped backslash ends the string at the next quote: what follows is bare.
    EXPECT_TRUE(refused("a = \"x\\\\\" Ж\n"));
    // A literal string has no escapes: its backslash ends nothing.
    EXPECT_TRUE(refused("a = 'x\\' Ж\n"));
    // Past a multi-line string's closing quotes (and up to two more of them), text is bare again.
    EXPECT_TRUE(refused("a = \"\"\"x\"\"\"\"\" Ж\n"));
    EXPECT_TRUE(refused("a = '''x''' Ж\n"));
    // A comment ends with its line; a one-line string never closed does too (the parser says it).
    auto e = refused("# Ж\na = \"open\nb = Ж\n");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->where().line, 3u);
}

TEST(TomlGuard, LinesCountedThroughMultiLineStrings) {
    auto e = refused("a = \"\"\"\n1\n2\\\n3\n\"\"\"\nb = '''\n4\n'''\nc = é\n");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->where().line, 9u);
    EXPECT_EQ(e->where().column, 5u);
}

TEST(TomlGuard, ByteThatIsNoUtf8ShownInHex) {
    auto e = refused(std::string("a = 1\nb = \xFF\n"));
    ASSERT_TRUE(e);
    EXPECT_EQ(e->where().line, 2u);
    EXPECT_NE(std::string(e->what()).find("byte 0xFF"), std::string::npos) << e->what();
    auto cut = refused(std::string("b = \xD0"));  // a character cut off at the end of the file
    ASSERT_TRUE(cut);
    EXPECT_NE(std::string(cut->what()).find("byte 0xD0"), std::string::npos) << cut->what();
}

}  // namespace
