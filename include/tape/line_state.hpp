// Small state machines of the serial line and of the character stream, fed a byte at a time.
#pragma once

#include <cstdint>

namespace tape {

inline constexpr std::uint8_t dc1 = 0x11;  ///< XON, start reader
inline constexpr std::uint8_t dc2 = 0x12;  ///< punch on
inline constexpr std::uint8_t dc3 = 0x13;  ///< XOFF, stop reader
inline constexpr std::uint8_t dc4 = 0x14;  ///< punch off

/// XON/XOFF as a sender sees it: DC3 pauses, DC1 resumes. The characters are configurable. Bit 8 is
/// not compared: a control that makes even parity on an 8N1 line sends DC3 as 0x93.
class XonXoff {
public:
    explicit XonXoff(std::uint8_t xon = dc1, std::uint8_t xoff = dc3) : xon_(xon & 0x7F), xoff_(xoff & 0x7F) {}
    /// Takes one byte from the other side; true when it was XON or XOFF (in either parity).
    bool receive(std::uint8_t b) {
        b &= 0x7F;
        if (b == xoff_) {
            if (!paused_) ++pauses_;
            paused_ = true;
            return true;
        }
        if (b == xon_) {
            paused_ = false;
            seen_xon_ = true;
            return true;
        }
        return false;
    }
    bool paused() const { return paused_; }
    bool seen_xon() const { return seen_xon_; }
    std::uint64_t pauses() const { return pauses_; }

private:
    std::uint8_t xon_, xoff_;
    bool paused_ = false, seen_xon_ = false;
    std::uint64_t pauses_ = 0;
};

/// Watches decoded characters for the end of a program (ГОСТ 20999-83 §1.9): the end of the block
/// holding M02 or M30, then the next '%'.
class ProgramEndWatch {
public:
    enum class Event { none, program_end, next_percent };

    Event feed(char c) {
        if (comment_) {
            comment_ = c != ')' && c != '\n';
            if (c != '\n') return Event::none;
        }
        if (in_m_ && c >= '0' && c <= '9') {
            if (m_value_ < 1000) m_value_ = m_value_ * 10 + (c - '0');
            m_digits_ = true;
            return Event::none;
        }
        if (in_m_ && (c == ' ' || c == '\t')) return Event::none;
        if (in_m_) close_m();
        switch (c) {
            case '(':
                comment_ = true;
                return Event::none;
            case 'M':
                in_m_ = true;
                m_value_ = 0;
                m_digits_ = false;
                return Event::none;
            case '\n':
                if (end_in_block_) {
                    end_in_block_ = false;
                    ended_ = true;
                    return Event::program_end;
                }
                return Event::none;
            case '%':
                if (ended_) {
                    ended_ = false;
                    return Event::next_percent;
                }
                return Event::none;
            default:
                return Event::none;
        }
    }
    /// True between the end of a program and the next '%'.
    bool ended() const { return ended_; }

private:
    void close_m() {
        in_m_ = false;
        if (m_digits_ && (m_value_ == 2 || m_value_ == 30)) end_in_block_ = true;
    }
    bool comment_ = false, in_m_ = false, m_digits_ = false, end_in_block_ = false, ended_ = false;
    int m_value_ = 0;
};

}  // namespace tape
