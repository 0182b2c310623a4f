// Strict reading of one TOML table for the machine profiles (toml_fields.hpp).
#include "machine/toml_fields.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tape/error.hpp"

namespace tape::machine_detail {
namespace {

std::string shown(const toml::node& n) {
    std::ostringstream out;
    if (n.is_string())
        out << '"' << n.value_or(std::string()) << '"';
    else if (n.is_table())
        out << "a table";
    else if (n.is_array())
        out << "an array";
    else
        n.visit([&out](auto&& v) { out << v; });
    return out.str().substr(0, 60);
}

std::string number_text(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

}  // namespace

Fields::Fields(const toml::table& table, std::string path, std::string_view file, std::string inherited_source,
               std::map<std::string, std::string>* sources)
    : table_(table), path_(std::move(path)), file_(file), source_(std::move(inherited_source)), sources_(sources) {
    if (const toml::node* s = table_.get("source")) {
        if (!s->is_string() || s->value_or(std::string()).empty()) wrong("source", "must be a non-empty string");
        source_ = *s->value<std::string>();
    }
}

const toml::node* Fields::node(std::string_view key) const {
    const toml::node* n = table_.get(key);
    if (!n) return nullptr;
    std::string own = source_;
    const toml::table* t = n->as_table();
    if (t && t->is_inline() && t->contains("value")) {
        Fields inner(*t, path_.empty() ? std::string(key) : path_ + "." + std::string(key), file_, source_);
        inner.only({"value"});
        own = inner.source();
        n = t->get("value");
    }
    if (sources_) (*sources_)[path_.empty() ? std::string(key) : path_ + "." + std::string(key)] = own;
    return n;
}

std::uint64_t Fields::line() const { return table_.source().begin.line; }

void Fields::fail_at(std::uint64_t line, std::string_view key, const std::string& message) const {
    std::string where = path_.empty() ? std::string(key) : key.empty() ? path_ : path_ + "." + std::string(key);
    throw Error(Errc::usage, Position{.line = line},
                file_ + ": line " + std::to_string(line) + ": " + where + ": " + message);
}

void Fields::fail(std::string_view key, const std::string& message) const {
    const toml::node* n = key.empty() ? nullptr : node(key);
    fail_at(n ? n->source().begin.line : line(), key, message);
}

void Fields::wrong(std::string_view key, const std::string& must) const {
    fail(key, must + ", not " + shown(*node(key)));
}

void Fields::only(std::initializer_list<std::string_view> known) const {
    for (auto&& [key, value] : table_) {
        if (key.str() == "source" || std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
        std::string list = "source";
        for (auto k : known) list += ", " + std::string(k);
        fail_at(value.source().begin.line, key.str(), "unknown key (known here: " + list + ")");
    }
}

std::optional<std::string> Fields::text(std::string_view key) const {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) wrong(key, "must be a string in quotes");
    return *n->value<std::string>();
}

std::string Fields::required_text(std::string_view key) const {
    auto t = text(key);
    if (!t || t->empty()) fail(key, "is required (a non-empty string)");
    return *t;
}

std::optional<bool> Fields::flag(std::string_view key) const {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    if (!n->is_boolean()) wrong(key, "must be true or false");
    return *n->value<bool>();
}

std::optional<double> Fields::number(std::string_view key, double min, double max) const {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    auto v = n->is_number() ? n->value<double>() : std::nullopt;
    if (!v || !std::isfinite(*v) || *v < min || *v > max)
        wrong(key, "must be a number from " + number_text(min) + " to " + number_text(max));
    return *v;
}

std::optional<std::int64_t> Fields::whole(std::string_view key, std::int64_t min, std::int64_t max) const {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    auto v = n->is_integer() ? n->value<std::int64_t>() : std::nullopt;
    if (!v || *v < min || *v > max)
        wrong(key, "must be a whole number from " + std::to_string(min) + " to " + std::to_string(max));
    return *v;
}

std::optional<std::string> Fields::choice(std::string_view key, std::initializer_list<std::string_view> allowed) const {
    const toml::node* n = node(key);
    if (!n) return std::nullopt;
    std::string v = n->is_string() ? *n->value<std::string>() : std::string();
    if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return v;
    std::string list;
    for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    wrong(key, "must be one of " + list);
}

std::vector<std::string> Fields::texts(std::string_view key) const {
    std::vector<std::string> out;
    const toml::node* n = node(key);
    if (!n) return out;
    if (!n->is_array()) wrong(key, "must be an array of strings");
    for (const auto& e : *n->as_array()) {
        if (!e.is_string() || e.value_or(std::string()).empty())
            fail_at(e.source().begin.line, key, "must be an array of non-empty strings");
        out.push_back(*e.value<std::string>());
    }
    return out;
}

const toml::table* Fields::table(std::string_view key) const {
    const toml::node* n = node(key);
    if (!n) return nullptr;
    if (!n->is_table()) wrong(key, "must be a table ([" + std::string(key) + "])");
    return n->as_table();
}

std::vector<const toml::table*> Fields::tables(std::string_view key) const {
    std::vector<const toml::table*> out;
    const toml::node* n = node(key);
    if (!n) return out;
    if (!n->is_array_of_tables()) wrong(key, "must be tables, one [[" + std::string(key) + "]] each");
    for (const auto& e : *n->as_array()) out.push_back(e.as_table());
    return out;
}

}  // namespace tape::machine_detail
