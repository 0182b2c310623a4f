// holes: a text picture of the tape, one frame a line:
//     |87654.321| comment
// tracks 8..4, the feed hole '.', tracks 3..1; 'o' (or 'O', '*') a hole, space no hole.
// Anything after the closing '|' is a comment (the writer puts the frame number and the decoded
// character there); blank lines and lines starting with '#' are comments too.
#include <algorithm>
#include <cstdio>

#include "image_formats.hpp"
#include "tape/error.hpp"
#include "tape/five_track.hpp"

namespace tape {
namespace {

constexpr std::string_view holes_extensions[] = {".holes", ".txt"};
constexpr int track_of_column[10] = {0, 8, 7, 6, 5, 4, 0, 3, 2, 1};  // column 6 is the feed hole

bool is_hole(char c) { return c == 'o' || c == 'O' || c == '*'; }

// The frame drawn on one line, or an explanation of what is wrong with it.
std::optional<Frame> parse_picture(std::string_view line, std::string* why) {
    if (line.size() < 11 || line[0] != '|' || line[10] != '|') {
        *why = "expected a frame picture |87654.321| (10 characters between the bars incl. the feed hole)";
        return std::nullopt;
    }
    if (line[6] != '.') {
        *why = "the feed hole column (between tracks 4 and 3) must be '.'";
        return std::nullopt;
    }
    Frame f = 0;
    for (int col = 1; col <= 9; ++col) {
        if (col == 6) continue;
        char c = line[col];
        if (is_hole(c))
            f |= static_cast<Frame>(1U << (track_of_column[col] - 1));
        else if (c != ' ') {
            *why = std::string("'") + c + "' in track " + std::to_string(track_of_column[col]) +
                   " is neither a hole 'o' nor a space";
            return std::nullopt;
        }
    }
    return f;
}

std::string_view trim_left(std::string_view s) {
    while (!s.empty() && (s[0] == ' ' || s[0] == '\t')) s.remove_prefix(1);
    return s;
}

void no_comment(std::string_view) {}

// fn(line, line_no, last) for each picture line until it returns false; comment(line) for each comment.
template <typename Fn, typename Comment = void (*)(std::string_view)>
void for_each_line(std::span<const std::uint8_t> bytes, Fn fn, Comment comment = no_comment) {
    std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::uint64_t line_no = 0;
    while (!text.empty()) {
        auto nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        ++line_no;
        line = trim_left(line);
        if (!line.empty() && line[0] == '#') comment(line);
        if (line.empty() || line[0] == '#') continue;
        if (!fn(line, line_no, text.empty())) return;
    }
}

int holes_match(std::span<const std::uint8_t> prefix) {
    int score = 0;
    for_each_line(prefix, [&](std::string_view line, std::uint64_t, bool last) {
        std::string why;
        if (parse_picture(line, &why))
            score = 100;
        else if (last && line[0] == '|')
            score = 60;  // a line cut off by the end of the prefix
        return false;
    });
    return score;
}

// Whole lines are parsed as they come; the unfinished last one waits for the next chunk.
class HolesReader : public ImageReader {
public:
    void read(std::span<const std::uint8_t> bytes, std::vector<Frame>& out) override {
        auto end = std::find(bytes.rbegin(), bytes.rend(), '\n').base();
        std::span<const std::uint8_t> lines(bytes.data(), static_cast<std::size_t>(end - bytes.begin()));
        if (!lines.empty() && !pending_.empty()) {
            pending_.insert(pending_.end(), lines.begin(), lines.end());
            parse(pending_, out);
            pending_.clear();
        } else if (!lines.empty()) {
            parse(lines, out);
        }
        pending_.insert(pending_.end(), end, bytes.end());
    }
    void finish(std::vector<Frame>& out) override {
        parse(pending_, out);
        pending_.clear();
    }
    std::optional<Code> declared_code() const override { return declared_; }

private:
    void parse(std::span<const std::uint8_t> lines, std::vector<Frame>& out) {
        std::uint64_t lines_before = lines_before_;
        auto header = [&](std::string_view comment) {
            if (!declared_ && !framed_) declared_ = header_code(comment);  // the header comes before the frames
        };
        auto picture = [&](std::string_view line, std::uint64_t line_no, bool) {
            std::string why;
            auto f = parse_picture(line, &why);
            if (!f) throw Error(Errc::bad_image, Position{.line = lines_before + line_no}, why);
            out.push_back(*f);
            framed_ = true;
            return true;
        };
        for_each_line(lines, picture, header);
        lines_before_ += static_cast<std::uint64_t>(std::count(lines.begin(), lines.end(), '\n'));
    }

    std::vector<std::uint8_t> pending_;  // an unfinished line
    std::uint64_t lines_before_ = 0;     // lines already parsed, so that errors count from the file's start
    std::optional<Code> declared_;
    bool framed_ = false;  // a frame was read: later comments are no header
};

class HolesWriter : public ImageWriter {
public:
    explicit HolesWriter(const ImageWriteOptions& options) : options_(options), number_(options.first_number) {
        if (options.annotate && options.annotate->five_track_table())
            labeler_.emplace(*options.annotate->five_track_table());
    }

    void write(std::span<const Frame> frames, std::string& out) override {
        if (options_.header && !header_written_) write_header(out);
        header_written_ = true;
        char number[24];
        for (Frame f : frames) {
            out += holes_picture(f);
            std::snprintf(number, sizeof number, " %6llu", static_cast<unsigned long long>(number_++));
            out += number;
            if (labeler_) {  // a 5-track frame means what the last shift made it mean
                out += labeler_->bad(f) ? "  ! " : "  ";
                out += labeler_->next(f);
            } else if (options_.annotate) {
                out += is_bad_frame(options_.annotate->kind(f)) ? "  ! " : "  ";
                out += options_.annotate->label(f);
            }
            out += '\n';
        }
    }
    void finish(std::string& out) override {
        if (options_.header && !header_written_) write_header(out);  // an empty tape still says what it is
        header_written_ = true;
    }

private:
    void write_header(std::string& out) const {
        out += "# tape holes picture: one frame a line, tracks 87654.321 ('.' = feed hole, 'o' = hole)\n";
        if (options_.annotate)
            out += "# code: " + std::string(code_name(options_.annotate->code())) + ", parity " +
                   std::string(parity_name(options_.annotate->parity())) + "; frame number, then character\n";
    }

    ImageWriteOptions options_;
    std::optional<FiveTrackLabeler> labeler_;
    std::uint64_t number_;
    bool header_written_ = false;
};

}  // namespace

ImageFormat holes_image_format() {
    return {.id = "holes",
            .description = "text picture, one frame a line: |87654.321|",
            .extensions = holes_extensions,
            .binary = false,
            .bytes_are_frames = false,
            .match = holes_match,
            .make_reader = []() -> std::unique_ptr<ImageReader> { return std::make_unique<HolesReader>(); },
            .make_writer = [](const ImageWriteOptions& options) -> std::unique_ptr<ImageWriter> {
                return std::make_unique<HolesWriter>(options);
            }};
}

}  // namespace tape
