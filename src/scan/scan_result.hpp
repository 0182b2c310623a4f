// The pieces of all pictures made one read (scan_result.cpp).
#pragma once

#include "scan/scan_geometry.hpp"

namespace tape::scan {

/// Stitches the pieces read from images (piece frames name their image by index into images), decides
/// the direction (or takes options.start), and gathers the doubts into runs.
ScanResult assemble(std::vector<ImageScan> images, std::vector<Piece> pieces, const ScanOptions& options);

}  // namespace tape::scan
