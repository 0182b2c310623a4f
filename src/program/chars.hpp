// The characters of part programs, as the loader and the macro checks both read them.
#pragma once

namespace tape::chars {

/// Space, tab, CR, and DC1-DC4 (a reader or punch switched on and off: RS-232 captures hold them).
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || (c >= '\x11' && c <= '\x14'); }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
inline bool is_lower(char c) { return c >= 'a' && c <= 'z'; }
inline bool is_letter(char c) { return is_upper(c) || is_lower(c); }
inline char upper(char c) { return is_lower(c) ? static_cast<char>(c - 'a' + 'A') : c; }

}  // namespace tape::chars
