#include "tape/input.hpp"

#include <algorithm>

#include "codec/utf8.hpp"
#include "tape/error.hpp"

namespace tape {
namespace {

constexpr std::size_t text_chunk_bytes = 128 << 10;
constexpr std::size_t kind_prefix_bytes = 64 << 10;  // what the choice of image or text looks at

Error text_fault_error(const TextFault& fault) {
    return Error(Errc::bad_text, fault.where, fault.what + ": a text program cannot hold it",
                 Hint{Hint::Action::read_as_image});
}

// Bytes already read, then the rest of the source: the image reader sees the file from its start.
class PrefixedSource : public ByteSource {
public:
    PrefixedSource(std::vector<std::uint8_t> prefix, std::unique_ptr<ByteSource> rest)
        : prefix_(std::move(prefix)), rest_(std::move(rest)) {}
    std::size_t read(std::span<std::uint8_t> buffer) override {
        if (given_ < prefix_.size()) {
            std::size_t n = std::min(buffer.size(), prefix_.size() - given_);
            std::copy_n(prefix_.begin() + static_cast<std::ptrdiff_t>(given_), n, buffer.begin());
            given_ += n;
            return n;
        }
        return rest_->read(buffer);
    }

private:
    std::vector<std::uint8_t> prefix_;
    std::size_t given_ = 0;
    std::unique_ptr<ByteSource> rest_;
};

}  // namespace

Input::Input(const std::string& path, const InputOptions& options) : options_(options) {
    open(std::make_unique<FileSource>(path), path);
    if (image_ && path != "-") read_doubts(path);
}

void Input::read_doubts(const std::string& path) {
    DoubtsFile file = read_doubts_beside(path);
    for (auto& d : file.frames)
        if (!d.decided || options_.decided_runs) doubts_.push_back(std::move(d));
    for (const auto& why : file.refused)
        notes_.push_back(Diagnostic{
            .code = Errc::bad_image, .message = doubts_file_for(path) + ": " + why, .severity = Severity::warning});
}

Input::Input(std::unique_ptr<ByteSource> source, const std::string& name, const InputOptions& options)
    : options_(options) {
    open(std::move(source), name);
}

Input::~Input() = default;

void Input::open(std::unique_ptr<ByteSource> source, const std::string& name) {
    bool image = options_.kind == InputKind::image;
    if (options_.kind == InputKind::automatic) {
        // An explicit format or an image's own extension decides; otherwise the content does: a holes
        // picture, clean UTF-8 text (a text program), a text with a stray byte (reported where the
        // byte is, not read as a strange tape), or anything else (a raw tape).
        const ImageFormat* by_name = name.empty() || name == "-" ? nullptr : image_format_for_path(name);
        image = options_.format || (by_name && !extension_is_ambiguous(name));
        if (!image) {
            text_ahead_.resize(kind_prefix_bytes);
            text_ahead_.resize(source->read_full(text_ahead_));
            const ImageFormat& by_content = detect_image_format(text_ahead_);
            bool picture = !by_content.binary && by_content.match(text_ahead_) >= 60;
            image = picture ||
                    (!is_program_text(std::span(text_ahead_)
                                          .first(utf8::whole_prefix({reinterpret_cast<const char*>(text_ahead_.data()),
                                                                     text_ahead_.size()}))) &&
                     !looks_like_damaged_text(text_ahead_));
        }
    }
    if (image) {
        if (!text_ahead_.empty()) source = std::make_unique<PrefixedSource>(std::move(text_ahead_), std::move(source));
        text_ahead_.clear();
        image_ = std::make_unique<ImageInput>(std::move(source), name, options_.format);
        return;
    }
    text_source_ = std::move(source);
    // A byte-order mark is no character of a program (an editor's habit): skipped, and said so.
    if (text_ahead_.empty()) {
        text_ahead_.resize(utf8_bom.size());
        text_ahead_.resize(text_source_->read_full(text_ahead_));
    }
    auto bom = std::span(reinterpret_cast<const std::uint8_t*>(utf8_bom.data()), utf8_bom.size());
    if (text_ahead_.size() >= bom.size() && std::equal(bom.begin(), bom.end(), text_ahead_.begin())) {
        text_ahead_.erase(text_ahead_.begin(), text_ahead_.begin() + static_cast<std::ptrdiff_t>(utf8_bom.size()));
        notes_.push_back(byte_order_mark_note());
    }
    // A text read whole by the look above: its DOS end-of-file mark is said now, with the other notes.
    if (text_ahead_.size() < kind_prefix_bytes && options_.kind == InputKind::automatic) {
        std::size_t mark = dos_end_of_file_at(text_ahead_);
        if (mark < text_ahead_.size() && is_program_text(text_ahead_)) {
            auto head = std::span(text_ahead_).first(mark);
            auto lines = static_cast<std::uint64_t>(std::count(head.begin(), head.end(), '\n'));
            notes_.push_back(dos_end_of_file_note(Position{.line = lines + 1, .byte = mark}));
            mark_noted_ = true;
        }
    }
}

std::span<const Frame> Input::next_frames() {
    if (!image_) throw Error(Errc::usage, "a text program has no frames");
    decode_options();  // detection reads ahead: the frames it read come first
    return image_->next();
}

std::optional<LeaderLabel> Input::label() {
    if (!image_) return std::nullopt;
    return image_->label();
}

const DecodeOptions& Input::decode_options() {
    if (decode_) return *decode_;
    DecodeOptions o = options_.decode;
    auto declared = image_ && options_.detect_code ? image_->declared_code() : std::nullopt;
    if (declared && *declared != Code::iso) {
        o.code = *declared;
    } else if (image_ && options_.detect_code) {
        if (image_->format().tracks == 5) {
            // Every frame is a character in both 5-track codes: only the reader can tell them apart.
            throw Error(Errc::unknown_code,
                        "a 5-track image: ITA2 and МТК-2 cannot be told apart from the frames, say which",
                        Hint{Hint::Action::use_code, "ita2 or mtk2"});
        }
        if (o.parity != Parity::even) {
            o.code = Code::iso;  // only ISO/ASCII tapes have a choice of parity
        } else {
            detect();
            if (detection_->code) {
                o.code = *detection_->code;
            } else if (o.keep_going && detection_->closest) {  // the text asked for all the same
                o.code = detection_->closest->code;
                o.parity = o.code == Code::iso ? detection_->closest->parity : Parity::even;
                closest_taken_ = true;
            } else {
                throw Error(Errc::unknown_code, detection_->reason, detection_->hint);
            }
        }
    }
    if (o.code == Code::eia && o.parity != Parity::even)
        throw Error(Errc::usage, "parity is for ISO tapes; EIA parity is always odd on track 5");
    if (is_five_track(o.code) && o.parity != Parity::even)
        throw Error(Errc::usage, "parity is for ISO tapes; 5-track codes carry none");
    if (is_telecode(o.code) && o.parity != Parity::even)
        throw Error(Errc::usage, "parity is for ISO tapes; the Elliott telecodes have their own");
    decode_ = o;
    return *decode_;
}

std::optional<Code> Input::declared_code() {
    if (!image_) return std::nullopt;
    return image_->declared_code();
}

const CodeDetection& Input::detect() {
    if (!image_) throw Error(Errc::usage, "a text program has no tape code");
    if (!detection_ && image_->format().tracks == 5) {  // not ISO or EIA read from a 5-track dump by chance
        CodeDetection five;
        five.kind = TapeKind::five_track;
        five.reason = "a 5-track image: ITA2 or МТК-2, which the frames cannot tell apart";
        five.hint = Hint{Hint::Action::use_five_track_code, {}};
        detection_ = std::move(five);
    }
    if (!detection_) detection_ = image_->detect(options_.decode.eia_table);
    return *detection_;
}

bool Input::next_text(DecodeResult& out) {
    if (ended_) return false;
    if (image_) {
        if (!decoder_) decoder_ = std::make_unique<Decoder>(decode_options());
        const auto& label = image_->label();  // before next(): it is looked for in the read-ahead
        auto frames = without_label(image_->next(), decoded_frames_, label, unlabelled_);
        decoded_frames_ += frames.size();
        if (frames.empty()) {
            ended_ = true;
            std::size_t had = out.text.size();
            decoder_->finish(out);  // a 5-track CR held back at the very end
            return out.text.size() > had;
        }
        if (!feed_with_doubts(frames, decoded_frames_ - frames.size(), out)) {
            out.complete = false;
            ended_ = true;
        }
        return true;
    }
    std::span<const std::uint8_t> piece;
    if (!text_ahead_.empty()) {
        piece = text_ahead_;
    } else {
        if (!text_buffer_) text_buffer_ = std::make_unique_for_overwrite<std::uint8_t[]>(text_chunk_bytes);
        piece = std::span(text_buffer_.get(), text_source_->read(std::span(text_buffer_.get(), text_chunk_bytes)));
    }
    if (piece.empty()) {
        ended_ = true;
        if (auto fault = text_checker_.finish()) throw text_fault_error(*fault);
        if (auto mark = text_checker_.end_of_file_mark(); mark && !mark_noted_)
            notes_.push_back(dos_end_of_file_note(Position{.line = mark->where.line, .byte = mark->offset}));
        return false;
    }
    if (auto fault = text_checker_.check(piece)) throw text_fault_error(*fault);
    // The checker lets DOS end-of-file marks through only where they end the text: they are not given.
    piece = piece.first(dos_end_of_file_at(piece));
    out.text.append(reinterpret_cast<const char*>(piece.data()), piece.size());
    text_ahead_.clear();
    return true;
}

// The decoder fed frames (the first of them frame `first`, from 0), with a Diagnostic for each doubt
// among them where it stands, in its line: at a frame written in doubt, or where a frame in doubt was
// left out. False where decoding stops (at a bad frame, or at a doubt unless keep_going).
bool Input::feed_with_doubts(std::span<const Frame> frames, std::uint64_t first, DecodeResult& out) {
    while (next_doubt_ < doubts_.size() && doubts_[next_doubt_].place() < first) ++next_doubt_;
    std::size_t given = 0;
    const std::uint64_t end = first + frames.size();
    while (next_doubt_ < doubts_.size()) {
        const DoubtfulFrame& d = doubts_[next_doubt_];
        // One left out after the chunk's last frame is said here; one written there, with its frame.
        if (d.place() > end || (d.place() == end && !d.left_out)) break;
        ++next_doubt_;
        auto upto = static_cast<std::size_t>(d.place() - first);
        if (!decoder_->feed(frames.subspan(given, upto - given), out)) return false;
        auto line = decoder_->line();  // before the frame in doubt, which may end the line
        given = upto;
        if (!d.left_out && !decoder_->feed(frames.subspan(given++, 1), out)) return false;
        Diagnostic said{.code = Errc::doubtful_frame,
                        .where = Position{.frame = std::max<std::uint64_t>(d.frame, 1), .line = line},
                        .message = d.message()};
        if (d.decided) {  // not in doubt: named, and decoding goes on
            said.rule = "run-decided";
            said.severity = Severity::note;
            out.diagnostics.push_back(std::move(said));
            continue;
        }
        ++doubtful_met_;
        out.diagnostics.push_back(std::move(said));
        if (!decode_->keep_going) return false;
    }
    return decoder_->feed(frames.subspan(given), out);
}

bool load_each(Input& input, ProgramVisitor& visitor, const LoadOptions& options) {
    ProgramLoader loader(visitor, options);
    DecodeResult piece;
    bool positions = input.is_image() && input.decode_options().positions;
    while (input.next_text(piece)) {
        loader.feed(piece.text,
                    positions ? std::span<const std::uint64_t>(piece.frame_of) : std::span<const std::uint64_t>());
        for (const auto& d : piece.diagnostics) visitor.finding(d);
        piece.text.clear();
        piece.frame_of.clear();
        piece.diagnostics.clear();
        if (!piece.complete) return false;
    }
    loader.finish();
    return true;
}

bool load(Input& input, LoadedTape& tape, const LoadOptions& options) {
    DecodeResult all;
    bool complete = true;
    while (input.next_text(all))
        if (!all.complete) {
            complete = false;
            break;
        }
    tape = load(std::move(all.text), std::move(all.frame_of), options);
    tape.findings.insert(tape.findings.begin(), all.diagnostics.begin(), all.diagnostics.end());
    return complete;
}

}  // namespace tape
