#include "tape/feed.hpp"

#include <algorithm>
#include <utility>

#include "tape/error.hpp"

namespace tape {
namespace {

// An image's frames as they are read. With its leader or trailer replaced, blank frames before the
// first punched one are dropped (the new leader goes out instead), and a run of blank frames is held
// until a punched frame shows it is inside the tape (then it goes out) or the tape ends (then it was
// the trailer). Memory: a chunk, and a count of blanks.
class ImageFeed : public FrameSource {
public:
    ImageFeed(Input& input, const FeedOptions& o) : input_(input), o_(o) {}

    std::span<const Frame> next() override {
        out_.clear();
        while (out_.empty() && !ended_) {
            auto chunk = input_.next_frames();
            if (chunk.empty()) {
                end();
                break;
            }
            for (Frame f : chunk) take(f);
        }
        return out_;
    }

private:
    void take(Frame f) {
        bool blank = f == blank_frame;
        if (!started_ && blank && o_.replace_leader) return;  // the old leader
        if (!started_ && !blank) {
            started_ = true;
            if (o_.replace_leader) out_.insert(out_.end(), o_.encode.leader, blank_frame);
        }
        if (blank && o_.replace_trailer) {
            ++held_;
            return;
        }
        out_.insert(out_.end(), held_, blank_frame);  // blanks inside the tape, or its leader
        held_ = 0;
        out_.push_back(f);
    }
    void end() {
        ended_ = true;
        if (!started_ && o_.replace_leader) out_.insert(out_.end(), o_.encode.leader, blank_frame);
        // A tape of blanks only keeps them as its leader (unless that is replaced too).
        if (!started_ && !o_.replace_leader) out_.insert(out_.end(), held_, blank_frame);
        if (o_.replace_trailer) out_.insert(out_.end(), o_.encode.trailer, blank_frame);
    }

    Input& input_;
    FeedOptions o_;
    std::vector<Frame> out_;
    std::uint64_t held_ = 0;
    bool started_ = false, ended_ = false;
};

// A text program, encoded whole: the dialect is judged from all of it and '%' put around it.
class TextFeed : public FrameSource {
public:
    explicit TextFeed(std::vector<Frame> frames) : frames_(std::move(frames)) {}
    std::span<const Frame> next() override {
        if (given_) return {};
        given_ = true;
        return frames_;
    }
    std::uint64_t total() const override { return frames_.size(); }

private:
    std::vector<Frame> frames_;
    bool given_ = false;
};

// The last line that is not blank is a lone '%' after the program (not the '%' that starts it).
bool ends_with_percent_line(std::string_view text) {
    auto last = text.find_last_not_of(" \t\r\n");
    if (last == std::string_view::npos || text[last] != '%') return false;
    auto line = text.rfind('\n', last);
    std::size_t from = line == std::string_view::npos ? 0 : line + 1;
    if (text.substr(from, last + 1 - from).find_first_not_of(" \t\r%") != std::string_view::npos) return false;
    return text.find_first_not_of(" \t\r\n") < from;
}

}  // namespace

std::string semicolons_to_line_ends(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    bool in_comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '\n') in_comment = false;
        if (c == '(') in_comment = true;
        if (c == ')') in_comment = false;
        if (c != ';' || in_comment) {
            out += c;
            continue;
        }
        while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
        std::size_t next = text.find_first_not_of(" \t\r", i + 1);
        if (next == std::string_view::npos || text[next] == '\n') {
            i = next == std::string_view::npos ? text.size() : next - 1;  // the line's own end follows
            if (next == std::string_view::npos) out += '\n';
        } else {
            out += '\n';
            i = next - 1;
        }
    }
    return out;
}

namespace {

std::string whole_text(Input& input) {
    DecodeResult all;
    while (input.next_text(all))
        if (all.text.size() > max_text_bytes)
            throw Error(Errc::bad_text, "the text holds more than " + std::to_string(max_text_bytes) +
                                            " characters: no part program is so long (is it a tape image? give "
                                            "--input image)");
    return std::move(all.text);
}

}  // namespace

std::unique_ptr<FrameSource> feed_source(Input& input, const FeedOptions& o, DialectChoice* chosen) {
    if (input.is_image()) return std::make_unique<ImageFeed>(input, o);
    std::string text = whole_text(input);
    DialectChoice choice{o.dialect, {}};
    if (o.dialect == Dialect::automatic) choice = guess_dialect(text);
    if (chosen) *chosen = choice;
    if (choice.dialect == Dialect::fanuc) text = semicolons_to_line_ends(text);
    // Nothing else is added: the text goes on tape as `tape encode` punches it (a last line without its
    // LF, a final '%' most often, stays so), unless a '%' is put after it, on a line of its own.
    if (o.percent) {
        auto first = text.find_first_not_of(" \t\r\n");
        if (first == std::string::npos || text[first] != '%') text.insert(0, "%\n");
        if (!ends_with_percent_line(text)) text += text.empty() || text.back() == '\n' ? "%" : "\n%";
    }
    return std::make_unique<TextFeed>(encode(text, o.encode));
}

std::vector<Frame> frames_to_send(Input& input, const FeedOptions& o, DialectChoice* chosen) {
    auto source = feed_source(input, o, chosen);
    std::vector<Frame> frames;
    for (auto chunk = source->next(); !chunk.empty(); chunk = source->next())
        frames.insert(frames.end(), chunk.begin(), chunk.end());
    return frames;
}

}  // namespace tape
