// Machine profiles: what one control is, beyond the dialect it builds on. ГОСТ 20999-83 leaves to "the
// format of the specific control" how many digits each address takes, the control's own G and M codes,
// its feed and speed code tables; a profile holds them, with the machine's kind, units per pulse, axis
// ranges, rapid rates, arc tolerance and line settings, each value with where it comes from (a manual,
// the seeds, "guess"). Profiles are TOML files (data/machines/*.toml, compiled in and installed with the
// code tables; a user's own in ~/.config/tape/machines/ or given by path); the format is in
// data/machines/README.md.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tape/code.hpp"
#include "tape/device.hpp"
#include "tape/dialect.hpp"
#include "tape/format_spec.hpp"

namespace tape {

enum class MachineKind { lathe, mill };
std::string_view machine_kind_name(MachineKind k);

/// A G or M code of the control, as its documentation names it.
struct MachineCode {
    char address = 0;  ///< 'G' or 'M'
    int code = 0;
    std::string meaning;     ///< in English
    std::string meaning_ru;  ///< as the Russian documentation names it, or ""
    std::string group;       ///< the codes of one group replace each other ("motion"), or "" for none
    std::string mode;        ///< the word format mode it selects (FormatMode::name), or ""
    std::string source;
    std::uint64_t line = 0;  ///< where it stands in its file
};

/// A word format that format-changing codes select: while it is in effect the dimension words of
/// `addresses` take exactly `digits` digits (the Н22-1М's G10/G20/G30 "long dimensions", six).
struct FormatMode {
    std::string name;       ///< "short", "normal", "long"
    std::string addresses;  ///< "XZIK"
    int digits = 0;
    std::string source;
    FormatSpec spec;  ///< the profile's format with these addresses at `digits` digits
};

/// A row of the feed code table: a feed word's first digit as the control reads it.
struct FeedCode {
    int first_digit = 0;
    std::string meaning;     ///< in English
    std::string meaning_ru;  ///< as the Russian documentation names it, or ""
    double factor = 1;       ///< the feed the machine runs at is the rest of the word times this; 0: rapid
    std::string source;
};

/// A row of the spindle speed code table.
struct SpeedCode {
    int code = 0;
    double rpm = 0;
    std::string source;
};

/// An axis: its pulse, travel and rapid rate, as far as known (0 or nullopt: not known).
struct MachineAxis {
    char name = 0;
    double mm_per_pulse = 0;  ///< the value of one unit of the axis's words; 0: words are millimetres
    std::optional<double> min_mm{}, max_mm{};
    std::string source;
};

/// The serial line and reader the control takes programs through.
struct MachineLine {
    std::optional<Code> code{};
    std::optional<Parity> parity{};
    unsigned baud = 0;  ///< 0: not known
    int data_bits = 0, stop_bits = 0;
    std::optional<Flow> flow{};
    bool dc_codes = false;                ///< the control sends DC1 to start and DC3 to stop (wait for DC1)
    double reader_frames_per_second = 0;  ///< the control's tape reader; 0: not known
    std::string source;
};

struct MachineProfile {
    std::string name;  ///< "16k20f3s5": what --machine takes
    std::string title;
    std::vector<std::string> aliases;
    MachineKind kind = MachineKind::mill;
    bool diameter_programming = false;  ///< lathes: X words are diameters
    Dialect dialect = Dialect::gost;
    FormatSpec format;         ///< ГОСТ 20999-83 §9: the widest form of each address
    std::string initial_mode;  ///< the format mode at the start of a program, or "" (none)
    std::vector<FormatMode> modes;
    std::string prefixed;  ///< addresses whose first digit is 0 or 1 (1: after the machine's acknowledgement)
    std::vector<MachineCode> codes;
    char feed_table_address = 0;       ///< 'F' when the first digit of a feed word is a table code, else 0
    std::vector<FeedCode> feed_codes;  ///< the complete table when feed_table_address is set
    std::vector<SpeedCode> speed_codes;
    bool speed_table_complete = false;  ///< false: a code not in speed_codes may still be the control's
    std::vector<MachineAxis> axes;
    std::map<char, double> rapid_mm_per_min;  ///< by axis
    double arc_tolerance_mm = 0;              ///< an arc's radii may differ by this much ...
    double arc_tolerance_relative = 0;        ///< ... or this fraction of the radius, whichever is larger
    MachineLine line;
    /// Where each value of the profile's top level and tables comes from, by key ("kind", "format",
    /// "arc_tolerance_mm", "axis.X"): what `tape machines show` prints beside it.
    std::map<std::string, std::string> sources;
    std::string file;  ///< where it was read from: a path, or "built-in"

    const MachineCode* find_code(char address, int code) const;
    const FormatMode* find_mode(std::string_view name) const;
    const MachineAxis* find_axis(char name) const;
    const FeedCode* find_feed_code(int first_digit) const;
    const SpeedCode* find_speed_code(int code) const;
};

/// Reads a profile. Strict: an unknown key, a value of the wrong type or out of range, a format the §9
/// notation does not read, a code or table row given twice, a mode no code names: Error(Errc::usage)
/// whose message starts with "FILE: line N: KEY:". The text must be UTF-8 TOML.
MachineProfile parse_machine_profile(std::string_view text, std::string_view file);

/// One profile that comes with tape (data/machines/NAME.toml, compiled in).
struct BundledMachine {
    std::string_view name;
    std::string_view text;
};
std::vector<BundledMachine> bundled_machines();

/// Where a user keeps profiles: $XDG_CONFIG_HOME/tape/machines, else ~/.config/tape/machines ("" when
/// neither is set).
std::string user_machine_folder();

/// A profile by what --machine was given: a path (with a '/' or ending in .toml), a user's own by file
/// name in user_machine_folder(), or a bundled one by name or alias (case as written, or lowercase).
/// Throws Error(Errc::usage) naming the profiles there are when none matches, and the parse errors.
MachineProfile load_machine(std::string_view name_or_path);

/// A serial: device string with the profile's line settings (baud, bits, stop, flow, and on a 7-bit line
/// the UART's parity, which stands for track 8) for the keys the string does not give; the string's own
/// keys win. Another device is returned as it is: its line is not a serial port's.
std::string device_with_machine_line(const std::string& device, const MachineLine& line);

/// Every profile there is: the user's first (they hide a bundled one of the same name), then the
/// bundled. A user's file that does not parse is listed, broken, with the error (its line and key) as
/// its title.
struct MachineListing {
    std::string name, title, file;
    bool bundled = false;
    bool broken = false;
};
std::vector<MachineListing> list_machines();

}  // namespace tape
