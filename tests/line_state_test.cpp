// Pure parts of the device layer, on byte arrays: XON/XOFF, the end-of-program watch, serial settings.
#include "tape/line_state.hpp"

#include <gtest/gtest.h>

#include <string>

#include "device/serial_termios.hpp"
#include "tape/error.hpp"
#include "tape/serial_settings.hpp"

using namespace tape;

TEST(XonXoff, PausesOnDc3ResumesOnDc1) {
    XonXoff x;
    EXPECT_FALSE(x.paused());
    EXPECT_TRUE(x.receive(dc3));
    EXPECT_TRUE(x.paused());
    EXPECT_FALSE(x.receive('A'));
    EXPECT_TRUE(x.paused());
    x.receive(dc3);  // a second XOFF is still one pause
    EXPECT_EQ(x.pauses(), 1U);
    x.receive(dc1);
    EXPECT_FALSE(x.paused());
    EXPECT_TRUE(x.seen_xon());
}

TEST(XonXoff, ConfigurableCharacters) {
    XonXoff x('Q', 'S');
    EXPECT_FALSE(x.receive(dc3));
    EXPECT_TRUE(x.receive('S'));
    EXPECT_TRUE(x.paused());
    x.receive('Q');
    EXPECT_FALSE(x.paused());
}

// 0x93 is DC3 with the parity bit an even-parity control sets on an 8N1 line; 0x91 DC1 with odd parity.
TEST(XonXoff, TakesFlowCharactersInEitherParity) {
    XonXoff x;
    EXPECT_TRUE(x.receive(0x93));
    EXPECT_TRUE(x.paused());
    EXPECT_TRUE(x.receive(0x91));
    EXPECT_FALSE(x.paused());
    EXPECT_TRUE(x.seen_xon());
    EXPECT_FALSE(x.receive(0x94));
    XonXoff configured(0x91, 0x93);  // given with the parity bit: the same characters
    EXPECT_TRUE(configured.receive(dc3));
    EXPECT_TRUE(configured.paused());
}

namespace {
std::vector<ProgramEndWatch::Event> events(const std::string& text) {
    ProgramEndWatch w;
    std::vector<ProgramEndWatch::Event> out;
    for (char c : text)
        if (auto e = w.feed(c); e != ProgramEndWatch::Event::none) out.push_back(e);
    return out;
}
using E = ProgramEndWatch::Event;
}  // namespace

TEST(ProgramEndWatch, EndOfBlockWithM02ThenPercent) {
    EXPECT_EQ(events("%\nN1 G01 X1\nN2 M02\n%"), (std::vector<E>{E::program_end, E::next_percent}));
    EXPECT_EQ(events("%\nN1 M30\n"), (std::vector<E>{E::program_end}));
    EXPECT_EQ(events("%\nN1 M 0 2\n%"), (std::vector<E>{E::program_end, E::next_percent}));
}

TEST(ProgramEndWatch, NotFooledByOtherWordsOrComments) {
    EXPECT_TRUE(events("%\nN1 M03\nN2 M20 (M02)\nN3 M302\n%").empty());
    EXPECT_TRUE(events("%\nN1 X2 M0\n%").empty());
    EXPECT_EQ(events("%\nN1 (END) M02 (BYE)\n%"), (std::vector<E>{E::program_end, E::next_percent}));
}

TEST(SerialSettings, ParsesEveryKey) {
    auto s = parse_serial_settings("/dev/ttyUSB0?baud=4800&bits=7&parity=even&stop=2&flow=rtscts");
    EXPECT_EQ(s.path, "/dev/ttyUSB0");
    EXPECT_EQ(s.baud, 4800U);
    EXPECT_EQ(s.data_bits, 7);
    EXPECT_EQ(s.parity, SerialParity::even);
    EXPECT_EQ(s.stop_bits, 2);
    EXPECT_EQ(s.flow, Flow::rtscts);
    EXPECT_DOUBLE_EQ(s.chars_per_second(), 4800.0 / 11);
    auto d = parse_serial_settings("/dev/ttyS0");
    EXPECT_EQ(d.baud, 9600U);
    EXPECT_EQ(d.data_bits, 8);
    EXPECT_EQ(d.flow, Flow::xonxoff);
}

TEST(SerialSettings, RejectsWhatIsNotThere) {
    for (const char* bad : {"", "?baud=9600", "/dev/x?baud=9601", "/dev/x?bits=6", "/dev/x?parity=mark",
                            "/dev/x?speed=9600", "/dev/x?flow=dtr", "/dev/x?bits=7", "/dev/x?stop=3", "/dev/x?baud"}) {
        try {
            parse_serial_settings(bad);
            ADD_FAILURE() << "accepted " << bad;
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), Errc::usage) << bad;
        }
    }
}

// Pseudo-terminals refuse 7-bit and parity settings, so the termios is checked as built.
TEST(SerialSettings, TermiosForIso7E2) {
    termios t = make_termios(parse_serial_settings("/dev/x?baud=9600&bits=7&parity=even&stop=2&flow=xonxoff"));
    EXPECT_EQ(t.c_cflag & CSIZE, static_cast<tcflag_t>(CS7));
    EXPECT_TRUE(t.c_cflag & PARENB);
    EXPECT_FALSE(t.c_cflag & PARODD);
    EXPECT_TRUE(t.c_cflag & CSTOPB);
    EXPECT_FALSE(t.c_cflag & CRTSCTS);
    EXPECT_FALSE(t.c_iflag & IXON);  // tape does XON/XOFF itself: it must see DC1 and DC3
    EXPECT_FALSE(t.c_iflag & IXOFF);
    EXPECT_TRUE(t.c_iflag & INPCK);
    EXPECT_FALSE(t.c_lflag & (ICANON | ECHO | ISIG));
    EXPECT_FALSE(t.c_oflag & OPOST);
    EXPECT_EQ(cfgetospeed(&t), static_cast<speed_t>(B9600));
    EXPECT_EQ(cfgetispeed(&t), static_cast<speed_t>(B9600));
}

TEST(SerialSettings, TermiosFor8N1RtsCts) {
    termios t = make_termios(parse_serial_settings("/dev/x?baud=38400&parity=odd&bits=8&flow=rtscts"));
    EXPECT_EQ(t.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
    EXPECT_TRUE(t.c_cflag & PARODD);
    EXPECT_TRUE(t.c_cflag & CRTSCTS);
    EXPECT_FALSE(t.c_cflag & CSTOPB);
    EXPECT_EQ(cfgetospeed(&t), static_cast<speed_t>(B38400));
}
