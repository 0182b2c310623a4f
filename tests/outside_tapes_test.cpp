// Every tape image of ../shared/data/outside* (other people's tapes, not in the project) through
// `tape info --json` and `tape decode`, compared with what was judged by hand for each, in
// tests/outside_tapes.expect (the judgement is written next to each expectation there).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "process_util.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

// The tape images there: everything under a tapes/ folder, and the .ptap, .ptp and .bin files.
std::vector<std::string> outside_tapes(const fs::path& data_root) {
    std::vector<std::string> found;
    for (const auto& top : fs::directory_iterator(data_root)) {
        if (!top.is_directory() || !top.path().filename().string().starts_with("outside")) continue;
        for (const auto& e : fs::recursive_directory_iterator(top.path())) {
            if (!e.is_regular_file()) continue;
            std::string rel = fs::relative(e.path(), data_root).string();
            std::string ext = e.path().extension().string();
            if (rel.find("/tapes/") != std::string::npos || ext == ".ptap" || ext == ".ptp" || ext == ".bin")
                found.push_back(rel);
        }
    }
    std::sort(found.begin(), found.end());
    return found;
}

// FILE key=value ... # judgement
std::map<std::string, std::map<std::string, std::string>> expectations() {
    std::map<std::string, std::map<std::string, std::string>> all;
    std::istringstream in(read_text(std::string(TAPE_SOURCE_DIR) + "/tests/outside_tapes.expect"));
    for (std::string line; std::getline(in, line);) {
        line = line.substr(0, line.find('#'));
        std::istringstream fields(line);
        std::string file;
        if (!(fields >> file)) continue;
        auto& e = all[file];
        for (std::string kv; fields >> kv;) e[kv.substr(0, kv.find('='))] = kv.substr(kv.find('=') + 1);
    }
    return all;
}

// The value of "key": in a JSON text, as written (a string without its quotes), from the first match.
std::string json_value(const std::string& json, const std::string& key, std::size_t from = 0) {
    auto at = json.find("\"" + key + "\": ", from);
    if (at == std::string::npos) return "?";
    at += key.size() + 4;
    if (json[at] == '"') return json.substr(at + 1, json.find('"', at + 1) - at - 1);
    return json.substr(at, json.find_first_of(",}", at) - at);
}

struct Run {
    int status;
    std::string out, err;
};

Run run(const std::vector<std::string>& args) {
    TempDir dir;
    Process p(args, dir);
    int status = p.wait(std::chrono::seconds(60));
    return {status, read_text(dir.file("stdout")), p.err()};
}

// What info and decode say of one tape, in the keys of the expectations file.
std::map<std::string, std::string> observed(const std::string& path, const std::map<std::string, std::string>& want) {
    std::map<std::string, std::string> got;
    Run info = run({"info", "--json", path});
    const std::string& j = info.out;
    got["kind"] = json_value(j, "kind");
    got["code"] = json_value(j, "code");
    auto label = j.find("\"leader_label\": {");
    got["label"] = label == std::string::npos ? "none" : json_value(j, "kind", label);
    got["bad"] =
        std::to_string(std::stoull(json_value(j, "parity_errors")) + std::stoull(json_value(j, "not_in_code")));
    auto binary = j.find("\"binary\": {");
    got["binary"] = binary == std::string::npos ? "none" : json_value(j, "format", binary);
    if (binary != std::string::npos) {
        got["blocks"] = json_value(j, "block_count", binary);
        got["hold"] = json_value(j, "hold", binary);
        got["fail"] = json_value(j, "fail", binary);
        got["missing"] = json_value(j, "missing", binary);
    }
    got["decode"] = std::to_string(run({"decode", path}).status);
    if (want.count("to_bin")) got["to_bin"] = std::to_string(run({"decode", "--to", "bin", path}).status);
    return got;
}

}  // namespace

TEST(OutsideTapes, InfoAndDecodeSayWhatWasJudgedByHand) {
    if (shared_data_dir().empty()) GTEST_SKIP() << "../shared/data is absent: the outside tapes are not in the project";
    const fs::path data_root = shared_data_dir();
    auto expect = expectations();
    auto tapes = outside_tapes(data_root);
    ASSERT_FALSE(tapes.empty());
    for (const auto& rel : tapes) {
        SCOPED_TRACE(rel);
        auto want = expect.find(rel);
        if (want == expect.end()) {
            ADD_FAILURE() << "no expectation: judge it and add it to tests/outside_tapes.expect";
            continue;
        }
        auto got = observed((data_root / rel).string(), want->second);
        for (const auto& [key, value] : want->second) EXPECT_EQ(got[key], value) << key;
    }
    for (const auto& [file, _] : expect)
        EXPECT_TRUE(std::find(tapes.begin(), tapes.end(), file) != tapes.end()) << file << " is no longer there";
}
