// Pictures of a tape as reads (picture_reads.hpp).
#include "picture_reads.hpp"

#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "scan_report.hpp"
#include "tape/image.hpp"
#include "tape/picture.hpp"
#include "tape/scan.hpp"

namespace cli {

bool is_picture(const std::string& path) { return !tape::picture_format_for_path(path).empty(); }

PictureRead read_picture(const std::string& path) {
    if (!tape::scan_available()) fail(path, tape::Errc::io, std::string(tape::scan_unavailable_message()));
    note_input(path);
    std::vector<std::string> paths{path};
    tape::ScanResult r;
    try {
        r = tape::scan_images(paths);
    } catch (const tape::Error& e) {
        fail("", e);  // the message names the picture
    }
    for (const auto& n : r.images[0].notes) say(path, n);
    say_frame_doubts(path, r.doubts);
    PictureRead out;
    out.read.name = path;
    out.read.format = &tape::default_image_format();
    out.read.frames = std::move(r.frames);
    out.doubts = std::move(r.doubts);
    return out;
}

ReadsAndDoubts read_tapes_or_pictures(const std::vector<std::string>& paths) {
    ReadsAndDoubts out;
    for (const auto& path : paths) {
        if (!is_picture(path)) {
            out.reads.push_back(read_tape(path, ""));
            out.doubts.emplace_back();
            continue;
        }
        PictureRead p = read_picture(path);
        out.reads.push_back(std::move(p.read));
        out.doubts.push_back(std::move(p.doubts));
    }
    return out;
}

}  // namespace cli
