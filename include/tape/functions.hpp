// Preparatory (G) and miscellaneous (M) functions of ГОСТ 20999-83 tables 4-8, as data in one place.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace tape {

enum class Scope {
    modal,      ///< acts until replaced by a function of its group (or cancelled)
    one_block,  ///< acts only in the block where it stands
    unstated,   ///< the standard leaves it to the controller's documentation
};

struct NcFunction {
    char address;  ///< 'G' or 'M'
    int code;      ///< 0..99
    char group;    ///< G: 'a' 'c' 'e' 'f' 'j' 'k' 'l' (table 4), 0 for none
    Scope scope;
    std::string_view ru;  ///< the standard's name
    std::string_view en;
};

/// All functions the standard defines, G then M, by code.
std::span<const NcFunction> nc_functions();
/// The function G<code> or M<code>, or nullptr when the standard leaves it undefined.
const NcFunction* find_nc_function(char address, long long code);

}  // namespace tape
