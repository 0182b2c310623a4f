// Strict reading of one TOML table for the machine profiles: every key must be known, every value of
// its type and range, and every mistake is an Error naming the file, the line and the key.
#pragma once

#include <toml++/toml.h>

#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tape::machine_detail {

/// One table of a profile being read: `path` names it in messages ("format.mode[2]"), `source` is the
/// source its values have unless one of them says otherwise. A value may be written plain or as
/// { value = ..., source = "..." }; the source of each value read is put in `sources` under
/// "path.key" when sources is given.
class Fields {
public:
    Fields(const toml::table& table, std::string path, std::string_view file, std::string inherited_source,
           std::map<std::string, std::string>* sources = nullptr);

    /// Throws for a key not in `known`.
    void only(std::initializer_list<std::string_view> known) const;
    /// The table's own "source", or the one it inherits.
    const std::string& source() const { return source_; }
    const std::string& path() const { return path_; }
    std::uint64_t line() const;

    bool has(std::string_view key) const { return table_.contains(key); }
    std::optional<std::string> text(std::string_view key) const;
    std::string required_text(std::string_view key) const;
    std::optional<bool> flag(std::string_view key) const;
    std::optional<double> number(std::string_view key, double min, double max) const;
    std::optional<std::int64_t> whole(std::string_view key, std::int64_t min, std::int64_t max) const;
    std::optional<std::string> choice(std::string_view key, std::initializer_list<std::string_view> allowed) const;
    /// An array of strings (aliases).
    std::vector<std::string> texts(std::string_view key) const;
    /// A sub-table, or nullptr.
    const toml::table* table(std::string_view key) const;
    /// The tables of an array of tables ([[key]]), empty when absent.
    std::vector<const toml::table*> tables(std::string_view key) const;

    /// Throws the Error for `key` (its line when the key is there, else the table's).
    [[noreturn]] void fail(std::string_view key, const std::string& message) const;
    [[noreturn]] void fail_at(std::uint64_t line, std::string_view key, const std::string& message) const;

private:
    const toml::node* node(std::string_view key) const;
    [[noreturn]] void wrong(std::string_view key, const std::string& must) const;

    const toml::table& table_;
    std::string path_;
    std::string file_;
    std::string source_;
    std::map<std::string, std::string>* sources_;
};

}  // namespace tape::machine_detail
