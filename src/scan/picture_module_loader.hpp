// The picture module (picture_module.hpp) loaded on first use, and its failures made Errors.
#pragma once

#include <string>
#include <utility>

#include "scan/picture_module.hpp"

namespace tape::picture_module {

/// The module's table, loaded once. Throws Error(Errc::io) saying why when this build has no OpenCV,
/// or the module or a library it needs is not installed.
const Api& api();

/// Empty when the module is loaded; else what api() throws.
const std::string& unavailable_reason();

/// Calls one of the module's functions; its Failure becomes an Error.
template <class Function, class... Args>
void call(Function function, Args&&... args) {
    if (Failure failure = function(std::forward<Args>(args)...)) throw Error(failure.code, std::move(failure.message));
}

}  // namespace tape::picture_module
