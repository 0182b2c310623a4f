// The code tables of ../shared/spec/tape-codes.md, copied row by row from the spec (not from the
// implementation), so the tests check the code against the normative reference.
#pragma once

struct SpecRow {
    char character;
    unsigned char frame;
    const char* holes;
    const char* name;
};

// Section 2: ISO 7-bit code with even parity on track 8.
inline constexpr SpecRow spec_iso_rows[] = {
    {'\x00', 0x00, "|     .   |", "NUL"}, {'\x08', 0x88, "|o   o.   |", "BS"}, {'\x09', 0x09, "|    o.  o|", "HT"},
    {'\n', 0x0A, "|    o. o |", "LF"},    {'\r', 0x8D, "|o   o.o o|", "CR"},   {'\x0e', 0x8E, "|o   o.oo |", "SO"},
    {'\x0f', 0x0F, "|    o.ooo|", "SI"},  {' ', 0xA0, "|o o  .   |", "SP"},    {'%', 0xA5, "|o o  .o o|", "%"},
    {'(', 0x28, "|  o o.   |", "("},      {')', 0xA9, "|o o o.  o|", ")"},     {'+', 0x2B, "|  o o. oo|", "+"},
    {',', 0xAC, "|o o o.o  |", ","},      {'-', 0x2D, "|  o o.o o|", "-"},     {'.', 0x2E, "|  o o.oo |", "."},
    {'/', 0xAF, "|o o o.ooo|", "/"},      {'0', 0x30, "|  oo .   |", "0"},     {'1', 0xB1, "|o oo .  o|", "1"},
    {'2', 0xB2, "|o oo . o |", "2"},      {'3', 0x33, "|  oo . oo|", "3"},     {'4', 0xB4, "|o oo .o  |", "4"},
    {'5', 0x35, "|  oo .o o|", "5"},      {'6', 0x36, "|  oo .oo |", "6"},     {'7', 0xB7, "|o oo .ooo|", "7"},
    {'8', 0xB8, "|o ooo.   |", "8"},      {'9', 0x39, "|  ooo.  o|", "9"},     {':', 0x3A, "|  ooo. o |", ":"},
    {'A', 0x41, "| o   .  o|", "A"},      {'B', 0x42, "| o   . o |", "B"},     {'C', 0xC3, "|oo   . oo|", "C"},
    {'D', 0x44, "| o   .o  |", "D"},      {'E', 0xC5, "|oo   .o o|", "E"},     {'F', 0xC6, "|oo   .oo |", "F"},
    {'G', 0x47, "| o   .ooo|", "G"},      {'H', 0x48, "| o  o.   |", "H"},     {'I', 0xC9, "|oo  o.  o|", "I"},
    {'J', 0xCA, "|oo  o. o |", "J"},      {'K', 0x4B, "| o  o. oo|", "K"},     {'L', 0xCC, "|oo  o.o  |", "L"},
    {'M', 0x4D, "| o  o.o o|", "M"},      {'N', 0x4E, "| o  o.oo |", "N"},     {'O', 0xCF, "|oo  o.ooo|", "O"},
    {'P', 0x50, "| o o .   |", "P"},      {'Q', 0xD1, "|oo o .  o|", "Q"},     {'R', 0xD2, "|oo o . o |", "R"},
    {'S', 0x53, "| o o . oo|", "S"},      {'T', 0xD4, "|oo o .o  |", "T"},     {'U', 0x55, "| o o .o o|", "U"},
    {'V', 0x56, "| o o .oo |", "V"},      {'W', 0xD7, "|oo o .ooo|", "W"},     {'X', 0xD8, "|oo oo.   |", "X"},
    {'Y', 0x59, "| o oo.  o|", "Y"},      {'Z', 0x5A, "| o oo. o |", "Z"},     {'\x7f', 0xFF, "|ooooo.ooo|", "DEL"},
};

// Section 3: EIA RS-244, odd parity on track 5. Blank tape has no character and is tested apart.
inline constexpr SpecRow spec_eia_rows[] = {
    {'0', 0x20, "|  o  .   |", "0"},
    {'1', 0x01, "|     .  o|", "1"},
    {'2', 0x02, "|     . o |", "2"},
    {'3', 0x13, "|   o . oo|", "3"},
    {'4', 0x04, "|     .o  |", "4"},
    {'5', 0x15, "|   o .o o|", "5"},
    {'6', 0x16, "|   o .oo |", "6"},
    {'7', 0x07, "|     .ooo|", "7"},
    {'8', 0x08, "|    o.   |", "8"},
    {'9', 0x19, "|   oo.  o|", "9"},
    {'A', 0x61, "| oo  .  o|", "A"},
    {'B', 0x62, "| oo  . o |", "B"},
    {'C', 0x73, "| ooo . oo|", "C"},
    {'D', 0x64, "| oo  .o  |", "D"},
    {'E', 0x75, "| ooo .o o|", "E"},
    {'F', 0x76, "| ooo .oo |", "F"},
    {'G', 0x67, "| oo  .ooo|", "G"},
    {'H', 0x68, "| oo o.   |", "H"},
    {'I', 0x79, "| oooo.  o|", "I"},
    {'J', 0x51, "| o o .  o|", "J"},
    {'K', 0x52, "| o o . o |", "K"},
    {'L', 0x43, "| o   . oo|", "L"},
    {'M', 0x54, "| o o .o  |", "M"},
    {'N', 0x45, "| o   .o o|", "N"},
    {'O', 0x46, "| o   .oo |", "O"},
    {'P', 0x57, "| o o .ooo|", "P"},
    {'Q', 0x58, "| o oo.   |", "Q"},
    {'R', 0x49, "| o  o.  o|", "R"},
    {'S', 0x32, "|  oo . o |", "S"},
    {'T', 0x23, "|  o  . oo|", "T"},
    {'U', 0x34, "|  oo .o  |", "U"},
    {'V', 0x25, "|  o  .o o|", "V"},
    {'W', 0x26, "|  o  .oo |", "W"},
    {'X', 0x37, "|  oo .ooo|", "X"},
    {'Y', 0x38, "|  ooo.   |", "Y"},
    {'Z', 0x29, "|  o o.  o|", "Z"},
    {' ', 0x10, "|   o .   |", "SP (space)"},
    {'+', 0x70, "| ooo .   |", "+"},
    {'-', 0x40, "| o   .   |", "-"},
    {'.', 0x6B, "| oo o. oo|", ". (period)"},
    {',', 0x3B, "|  ooo. oo|", ", (comma)"},
    {'/', 0x31, "|  oo .  o|", "/"},
    {'\x09', 0x3E, "|  ooo.oo |", "HT (tab)"},
    {'\n', 0x80, "|o    .   |", "EOB (end of block; ISO LF)"},
    {'%', 0x0B, "|    o. oo|", "ER rewind stop (ISO %)"},
    {'(', 0x1A, "|   oo. o |", "( control out (comment start)"},
    {')', 0x4A, "| o  o. o |", ") control in (comment end)"},
    {'\x08', 0x2A, "|  o o. o |", "BS (backspace)"},
    {'\x7f', 0x7F, "| oooo.ooo|", "DEL (delete, all holes)"},
};
