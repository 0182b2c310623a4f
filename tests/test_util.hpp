// Small helpers shared by the unit tests.
#pragma once

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tape/frame.hpp"

inline std::string sample_path(const std::string& name) { return std::string(TAPE_SOURCE_DIR) + "/tapes/" + name; }

inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

inline std::vector<tape::Frame> read_frames(const std::string& path) {
    std::string s = read_text(path);
    return {s.begin(), s.end()};
}
