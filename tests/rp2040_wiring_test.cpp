// The Pico's wiring has one source, firmware/rp2040/pins.hpp: docs/rp2040-wiring.md must carry its
// table row for row (scripts/rp2040-wiring.py --write puts it there), and the pins the firmware uses by
// name must be in the table with the direction the firmware gives them.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "rp2040/pins.hpp"
#include "test_util.hpp"

namespace {

std::vector<std::string> doc_rows() {
    std::string doc = read_text(std::string(TAPE_SOURCE_DIR) + "/docs/rp2040-wiring.md");
    auto begin = doc.find("<!-- pins:begin"), end = doc.find("<!-- pins:end -->");
    if (begin == std::string::npos || end == std::string::npos) return {};
    std::istringstream in(doc.substr(begin, end - begin));
    std::vector<std::string> rows;
    for (std::string line; std::getline(in, line);)
        if (line.rfind("| GP", 0) == 0) rows.push_back(line);
    return rows;
}

TEST(Rp2040Wiring, TheDocumentCarriesThePinHeadersTableRowForRow) {
    std::vector<std::string> expected;
    for (const auto& p : pico_pins::table)
        expected.push_back("| GP" + std::to_string(p.gpio) + " | " + p.connector + " | " + p.signal + " | " +
                           (p.dir == pico_pins::Dir::in ? "in" : "out") + " | " + p.shifting + " |");
    EXPECT_EQ(doc_rows(), expected) << "run: python3 scripts/rp2040-wiring.py --write";
}

TEST(Rp2040Wiring, EveryPinTheFirmwareNamesIsInTheTableOnceWithItsDirection) {
    using namespace pico_pins;
    std::set<unsigned> seen;
    for (const auto& p : table) {
        EXPECT_TRUE(seen.insert(p.gpio).second) << "GP" << +p.gpio << " twice";
        EXPECT_TRUE(p.gpio <= 22 || (p.gpio >= 25 && p.gpio <= 28))
            << "GP" << +p.gpio << " is not on the Pico's header";
    }
    auto dir_of = [](unsigned g) {
        for (const auto& p : table)
            if (p.gpio == g) return static_cast<int>(p.dir);
        return -1;
    };
    for (unsigned g = bus_first; g <= bus_strobe; ++g) EXPECT_EQ(dir_of(g), static_cast<int>(Dir::out)) << g;
    for (unsigned g = reader_first; g < reader_first + 8u; ++g) EXPECT_EQ(dir_of(g), static_cast<int>(Dir::in)) << g;
    for (unsigned g : {reader_start, reader_reverse, led}) EXPECT_EQ(dir_of(g), static_cast<int>(Dir::out)) << g;
    for (unsigned g :
         {control_run, reader_sprocket, reader_tape_out, punch_ready, punch_tape_out, control_reverse, control_rewind})
        EXPECT_EQ(dir_of(g), static_cast<int>(Dir::in)) << g;
    // The emulate role's default wiring (tapefw::Wiring: data 0..7, strobe 8, start/stop 9) is X3's.
    for (unsigned g = 0; g <= 9; ++g) EXPECT_TRUE(control_side(g)) << g;
    EXPECT_FALSE(control_side(reader_first));
}

}  // namespace
