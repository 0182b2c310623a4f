// PDP-8 RIM and BIN loader tapes (the formats are in tape/binary_tape.hpp), read a frame at a time. A
// section runs from the leader to the trailer (frames 0200); whether it is RIM or BIN shows only at its
// end (RIM pairs every word with its address; the last word of BIN is the checksum), so each word is
// loaded one word late, once the next one has come.
#include "binary_parser.hpp"

namespace tape {
namespace {

constexpr Frame leader_frame = 0200, rubout = 0377;
constexpr Frame origin_bit = 0100;
// A section follows a leader of at least this many 0200 frames. So the single 0200 of EIA's end of block,
// with EIA characters between, is no PDP-8 tape.
constexpr std::uint64_t leader_needed = 8;

bool field_setting(Frame f) { return (f & 0300) == 0300 && f != rubout; }

// The DEC loader forms a word by adding the low frame to the high one shifted (TAD), so a low frame
// with 0100 punched adds it: some tapes' checksum words are punched so.
std::uint16_t word_of(Frame high, Frame low) { return static_cast<std::uint16_t>(((high & 077) << 6) + low) & 07777; }

// One section between leader and trailer, as far as it has been read.
struct Section {
    std::uint64_t first = 0, last = 0;  // 0-based indexes of its first and last punched frames
    std::uint64_t punched = 0;
    std::uint32_t sum = 0;  // of every word frame taken
    std::uint64_t words = 0, origins = 0;
    std::uint32_t first_origin = 0;
    bool alternating = true;       // origin, data, origin, data ...: RIM
    bool fields = false;           // a field setting was punched (RIM has none)
    bool bad = false;              // a frame no loader takes (track 8 without a field setting, no origin first)
    std::optional<Frame> high{};   // the first frame of a word whose second has not come
    std::uint32_t high_field = 0;  // the field set when it came
    std::optional<std::pair<Frame, Frame>> last_word{};  // the last whole word, not yet loaded
    std::uint32_t last_word_field = 0;
    std::uint64_t last_word_end = 0;  // index of its second frame
};

class Pdp8Parser : public BinaryReader::Parser {
public:
    explicit Pdp8Parser(bool keep_image) : Parser(BinaryFormat::pdp8_bin, keep_image) {}

    void feed(std::span<const Frame> frames) override {
        for (Frame f : frames) {
            take(f);
            ++at_;
        }
    }

    void finish() override {
        blanks_ = 0;  // blank tape after the last punched frame is runout, not words of 0000
        if (section_) end_section(false);
    }

private:
    void take(Frame f) {
        if (f != blank_frame) ++tape_.punched;
        if (comment_) {  // between two rubouts: skipped by the loader
            comment_ = f != rubout;
            if (f != blank_frame) note_punched();
            return;
        }
        if (f == leader_frame) {
            if (section_) {
                flush_blanks();
                end_section(true);
            }
            ++leader_run_;
            return;
        }
        if (f == blank_frame) {
            if (section_) ++blanks_;  // words of 0000, unless only runout follows
            return;
        }
        if (!section_ && leader_run_ < leader_needed) {  // no leader before it: no loader would take it
            add_stray(1, at_);
            return;
        }
        if (!section_) section_ = Section{.first = at_};
        leader_run_ = 0;
        flush_blanks();
        note_punched();
        if (f == rubout) {
            comment_ = true;
        } else if (field_setting(f)) {
            section_->fields = true;
            next_field_ = static_cast<std::uint32_t>(f & 070) << 9;
        } else if (f & 0200) {
            section_->bad = true;
        } else {
            word_frame(f);
        }
    }

    void note_punched() {
        section_->last = at_;
        ++section_->punched;
    }

    void flush_blanks() {
        for (; blanks_ > 0; --blanks_) word_frame(blank_frame);
    }

    void word_frame(Frame f) {
        Section& s = *section_;
        s.sum += f;
        if (!s.high) {
            s.high = f;
            s.high_field = next_field_;
            return;
        }
        if (s.last_word) load(*s.last_word, s.last_word_field);
        s.last_word = std::pair(*s.high, f);
        s.last_word_field = s.high_field;
        s.last_word_end = at_;
        s.high.reset();
        bool origin = (s.last_word->first & origin_bit) != 0;
        if (s.words == 0 && !origin) s.bad = true;  // a loader starts at an origin
        s.alternating &= origin == (s.words % 2 == 0);
        ++s.words;
    }

    // A word that is not the section's last: an origin, or data stored where the origin points, in the
    // field set before the word began.
    void load(std::pair<Frame, Frame> w, std::uint32_t field) {
        Section& s = *section_;
        field_ = field;
        std::uint16_t value = word_of(w.first, w.second);
        if (w.first & origin_bit) {
            origin_ = value;
            if (s.origins++ == 0) s.first_origin = field_ | origin_;
            return;
        }
        store(field_ | origin_, value);
        origin_ = (origin_ + 1) & 07777;
        ++loaded_;
    }

    void end_section(bool trailer);

    std::optional<Section> section_;
    std::uint64_t at_ = 0;          // 0-based index of the frame being taken
    std::uint64_t blanks_ = 0;      // blank frames inside a section not yet taken as words
    std::uint64_t leader_run_ = 0;  // 0200 frames since the last section (blank tape among them)
    std::uint64_t loaded_ = 0;      // data words of the section loaded so far
    std::uint32_t field_ = 0, next_field_ = 0, origin_ = 0;
    bool comment_ = false;
};

void Pdp8Parser::end_section(bool trailer) {
    Section s = *section_;
    bool rim = s.alternating && s.words % 2 == 0 && !s.fields && !s.high;
    if (s.bad || s.words < 2) {
        add_stray(s.punched, s.first);
    } else {
        BinaryBlock b{.format = rim ? BinaryFormat::pdp8_rim : BinaryFormat::pdp8_bin,
                      .first = s.first,
                      .frames = s.last + 1 - s.first};
        if (rim) load(*s.last_word, s.last_word_field);  // RIM's last word is data, after its address
        if (!rim && trailer) {
            Frame high = s.last_word->first, low = s.last_word->second;
            std::uint16_t computed = static_cast<std::uint16_t>(s.sum - high - low) & 07777;
            std::uint16_t stored = word_of(high, low);
            b.checksum =
                ChecksumSpan{.state = stored == computed ? ChecksumSpan::State::holds : ChecksumSpan::State::fails,
                             .first = s.first,
                             .frames = s.last_word_end + 1 - s.first,
                             .stored = stored,
                             .computed = computed};
        } else if (!rim) {
            // Without its trailer the tape does not say which word is the checksum: none is checked or loaded.
            b.checksum = ChecksumSpan{.state = ChecksumSpan::State::missing, .first = s.first, .frames = b.frames};
            b.cut = true;
        }
        b.origin = section_->first_origin;
        b.origins = section_->origins;
        b.words = loaded_;
        if (s.high || !trailer) b.cut = true;  // a frame without its pair, or no trailer after it
        add_block(b);
    }
    section_.reset();
    loaded_ = 0;
    comment_ = false;
}

}  // namespace

std::unique_ptr<BinaryReader::Parser> make_pdp8_parser(bool keep_image) {
    return std::make_unique<Pdp8Parser>(keep_image);
}

std::uint16_t pdp8_bin_checksum(std::span<const Frame> frames) {
    std::uint32_t sum = 0;
    bool comment = false;
    for (Frame f : frames) {
        if (f == rubout) {
            comment = !comment;
            continue;
        }
        if (comment || field_setting(f) || f == leader_frame) continue;
        sum += f;
    }
    return static_cast<std::uint16_t>(sum & 07777);
}

}  // namespace tape
