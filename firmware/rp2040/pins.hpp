// The Raspberry Pi Pico's pins in the tape adapter: the one source of the wiring. The firmware takes
// its pin numbers from here, and docs/rp2040-wiring.md carries the same table for the soldering iron
// (tests/rp2040/pins_doc_test.py checks that the two agree, row for row).
//
// Three connectors: X1 toward a ФС-1501 reader, X2 toward a ПЛ-150-class punch, X3 toward a control
// (the emulate role: the adapter stands in for the control's reader). The punch's magnets and the data
// lines toward a control share GP0..GP8 through separate drivers; one role runs at a time (the core
// refuses EMULATE while the punch has rows, and PUNCH while emulating).
//
// No contact numbering of the ФС-1501's connector was found in a public source (man tape-usb(7),
// "Pinouts"): the table names each line by its function, and the contact is to be found on the unit
// with an oscilloscope before wiring (docs/adapter-protocol.md, "Connecting a ФС-1501").
// This header compiles on the host as well (no registers), for that check.
#pragma once

#include <cstdint>

namespace pico_pins {

enum class Dir : std::uint8_t { in, out };

struct Pin {
    std::uint8_t gpio;
    const char* connector;  ///< X1 reader, X2 punch, X3 control, or the Pico board itself
    const char* signal;
    Dir dir;
    const char* shifting;  ///< the level shifting between the Pico's 3.3 V and the line
};

// Lines from 5 V TTL (К155) outputs: a 74LVC245 at 3.3 V (5 V tolerant inputs); lines to 5 V inputs:
// a 74HCT245 at 5 V (takes 3.3 V as high); magnets: a ULN2803 Darlington sink at the punch's supply.
inline constexpr const char* from_ttl = "74LVC245 at 3.3 V (5 V tolerant inputs)";
inline constexpr const char* to_ttl = "74HCT245 at 5 V";
inline constexpr const char* magnet = "ULN2803 sink; and 74HCT245 at 5 V toward X3";

inline constexpr std::uint8_t bus_first = 0;      ///< GP0..GP7: tracks 1..8 out (punch magnets / X3 data)
inline constexpr std::uint8_t bus_strobe = 8;     ///< feed-hole magnet / X3 sprocket strobe
inline constexpr std::uint8_t control_run = 9;    ///< X3: the control's start/stop line (in)
inline constexpr std::uint8_t reader_first = 10;  ///< GP10..GP17: reader tracks 1..8 (in)
inline constexpr std::uint8_t reader_sprocket = 18;
inline constexpr std::uint8_t reader_start = 19;
inline constexpr std::uint8_t reader_reverse = 20;
inline constexpr std::uint8_t reader_tape_out = 21;
inline constexpr std::uint8_t punch_ready = 22;
inline constexpr std::uint8_t led = 25;  ///< the Pico's own LED: on while the reader is told to run
inline constexpr std::uint8_t punch_tape_out = 26;
inline constexpr std::uint8_t control_reverse = 27;
inline constexpr std::uint8_t control_rewind = 28;

inline constexpr Pin table[] = {
    {0, "X2/X3", "track 1 magnet / track 1 data to the control", Dir::out, magnet},
    {1, "X2/X3", "track 2 magnet / track 2 data to the control", Dir::out, magnet},
    {2, "X2/X3", "track 3 magnet / track 3 data to the control", Dir::out, magnet},
    {3, "X2/X3", "track 4 magnet / track 4 data to the control", Dir::out, magnet},
    {4, "X2/X3", "track 5 magnet / track 5 data to the control", Dir::out, magnet},
    {5, "X2/X3", "track 6 magnet / track 6 data to the control", Dir::out, magnet},
    {6, "X2/X3", "track 7 magnet / track 7 data to the control", Dir::out, magnet},
    {7, "X2/X3", "track 8 magnet / track 8 data to the control", Dir::out, magnet},
    {8, "X2/X3", "feed-hole magnet / sprocket strobe to the control", Dir::out, magnet},
    {9, "X3", "the control's start/stop", Dir::in, from_ttl},
    {10, "X1", "reader track 1", Dir::in, from_ttl},
    {11, "X1", "reader track 2", Dir::in, from_ttl},
    {12, "X1", "reader track 3", Dir::in, from_ttl},
    {13, "X1", "reader track 4", Dir::in, from_ttl},
    {14, "X1", "reader track 5", Dir::in, from_ttl},
    {15, "X1", "reader track 6", Dir::in, from_ttl},
    {16, "X1", "reader track 7", Dir::in, from_ttl},
    {17, "X1", "reader track 8", Dir::in, from_ttl},
    {18, "X1", "reader sprocket (synchronisation track)", Dir::in, from_ttl},
    {19, "X1", "reader start/stop (clutch and brake)", Dir::out, to_ttl},
    {20, "X1", "reader direction", Dir::out, to_ttl},
    {21, "X1", "reader tape out", Dir::in, from_ttl},
    {22, "X2", "punch ready (sync)", Dir::in, from_ttl},
    {25, "Pico", "LED: the reader is told to run", Dir::out, "none (on the board)"},
    {26, "X2", "punch tape out", Dir::in, from_ttl},
    {27, "X3", "the control's direction", Dir::in, from_ttl},
    {28, "X3", "the control's rewind", Dir::in, from_ttl},
};

/// The pins the emulate role may drive or watch (X3): a WIRING naming another pin leaves that line out.
inline constexpr bool control_side(unsigned gpio) {
    return gpio <= control_run || gpio == control_reverse || gpio == control_rewind;
}

}  // namespace pico_pins
