// Every tape image the tests can read: the project's sample tapes and every file of ../shared/data that
// reads as one (pictures left out), each with its frames, for tests that hold a rule against them all.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tape/error.hpp"
#include "tape/file_io.hpp"
#include "tape/image.hpp"
#include "tape/picture.hpp"
#include "test_util.hpp"

struct TapeFile {
    std::string path;
    std::vector<tape::Frame> frames;
};

inline std::vector<TapeFile> every_tape() {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(std::string(TAPE_SOURCE_DIR) + "/tapes"))
        files.push_back(e.path());
    if (!shared_data_dir().empty())
        for (const auto& e : std::filesystem::recursive_directory_iterator(shared_data_dir()))
            if (e.is_regular_file() && tape::picture_format_for_path(e.path().string()).empty())
                files.push_back(e.path());
    std::vector<TapeFile> tapes;
    for (const auto& path : files) {
        try {
            auto bytes = tape::read_file(path.string());
            tapes.push_back({path.string(), tape::detect_image_format(bytes).read(bytes)});
        } catch (const tape::Error&) {
            // no tape image: a text of notes
        }
    }
    return tapes;
}

/// How many tapes every_tape() finds at the least: the project's own samples in a clone alone, and more
/// than 20 with ../shared/data beside it.
inline std::size_t every_tape_minimum() { return shared_data_dir().empty() ? 15 : 21; }
