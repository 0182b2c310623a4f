// Restoration's repair of frames no read has right, and the report's line numbers (restore.cpp).
#pragma once

#include <cstddef>
#include <span>

#include "tape/restore.hpp"

namespace tape::detail {

/// The unresolved problems (indices into out.problems, in tape order): the single-hole changes of
/// what the reads saw that make a character of the code and fit the block, tried together with the
/// other damaged frames of the same block. A frame that every fitting choice gives one value is
/// inferred; the others stay as read with the values that fit listed.
void repair_unresolved(RestoreResult& out, std::span<const std::size_t> unresolved, const FrameCode& code,
                       Dialect dialect, const FormatSpec* spec);

/// Sets each written problem's line in the restored text.
void number_lines(RestoreResult& out, const FrameCode& code);

}  // namespace tape::detail
