// PDP-11 absolute loader tapes (the format is in tape/binary_tape.hpp): blocks of 001 000, byte count,
// load address, data and a checksum byte, read a frame at a time; blank frames between blocks are leader.
#include "binary_parser.hpp"

namespace tape {
namespace {

class Pdp11Parser : public BinaryReader::Parser {
public:
    explicit Pdp11Parser(bool keep_image) : Parser(BinaryFormat::pdp11_absolute, keep_image) {}

    void feed(std::span<const Frame> frames) override {
        for (Frame f : frames) {
            take(f);
            ++at_;
        }
    }

    void finish() override {
        if (state_ == State::between || state_ == State::after_end) return;
        if (state_ == State::second) {  // a lone 001 at the very end
            add_stray(1, block_.first);
            return;
        }
        block_.frames = at_ - block_.first;
        block_.cut = true;
        block_.checksum =
            ChecksumSpan{.state = ChecksumSpan::State::missing, .first = block_.first, .frames = block_.frames};
        add_block(block_);
    }

private:
    enum class State { between, second, count_low, count_high, address_low, address_high, data, checksum, after_end };

    void take(Frame f) {
        if (f != blank_frame) ++tape_.punched;
        sum_ = static_cast<std::uint8_t>(sum_ + f);
        switch (state_) {
            case State::between:
            case State::after_end:
                if (f == 1 && state_ == State::between) return start_block();
                if (f != blank_frame) add_stray(1, at_);
                return;
            case State::second:
                if (f == 0) {
                    state_ = State::count_low;
                    return;
                }
                add_stray(1, block_.first);  // the 001 began no block
                state_ = State::between;
                return take_again(f);
            case State::count_low:
                count_ = f;
                state_ = State::count_high;
                return;
            case State::count_high:
                count_ |= static_cast<std::uint32_t>(f) << 8;
                if (count_ < 6) return bad_header();
                state_ = State::address_low;
                return;
            case State::address_low:
                block_.origin = f;
                state_ = State::address_high;
                return;
            case State::address_high:
                block_.origin |= static_cast<std::uint32_t>(f) << 8;
                remaining_ = count_ - 6;
                block_.words = remaining_;
                state_ = remaining_ ? State::data : State::checksum;
                return;
            case State::data:
                store((block_.origin + block_.words - remaining_) & 0xFFFF, f);
                if (--remaining_ == 0) state_ = State::checksum;
                return;
            case State::checksum:
                return end_block(f);
        }
    }

    // The frame that ended a false start is looked at again as the first of what follows.
    void take_again(Frame f) {
        if (f != blank_frame) --tape_.punched;
        sum_ = static_cast<std::uint8_t>(sum_ - f);
        take(f);
    }

    void start_block() {
        block_ = BinaryBlock{.format = BinaryFormat::pdp11_absolute, .first = at_};
        sum_ = 1;
        state_ = State::second;
    }

    void bad_header() {
        add_stray(at_ + 1 - block_.first, block_.first);
        state_ = State::between;
    }

    void end_block(Frame stored) {
        block_.frames = at_ + 1 - block_.first;
        ChecksumSpan c{.state = sum_ == 0 ? ChecksumSpan::State::holds : ChecksumSpan::State::fails,
                       .first = block_.first,
                       .frames = block_.frames,
                       .stored = stored,
                       .computed = static_cast<std::uint8_t>(stored - sum_)};
        block_.checksum = c;
        block_.end = count_ == 6;
        add_block(block_);
        state_ = State::between;
        if (!block_.end) return;
        tape_.ended = true;
        tape_.start = block_.origin;
        state_ = State::after_end;
    }

    State state_ = State::between;
    BinaryBlock block_;
    std::uint64_t at_ = 0;  // 0-based index of the frame being taken
    std::uint32_t count_ = 0, remaining_ = 0;
    std::uint8_t sum_ = 0;
};

}  // namespace

std::unique_ptr<BinaryReader::Parser> make_pdp11_parser(bool keep_image) {
    return std::make_unique<Pdp11Parser>(keep_image);
}

std::uint8_t pdp11_checksum(std::span<const Frame> block) {
    std::uint8_t sum = 0;
    for (Frame f : block) sum = static_cast<std::uint8_t>(sum + f);
    return static_cast<std::uint8_t>(-sum);
}

}  // namespace tape
