#pragma once
#include <string>

namespace solidtex::io::detail {

// Codec libraries allocate what a length field claims before they find the file too short for it
// (a 691-byte PNG whose text chunk claims 1.29 GB; a 1.6 KB EXR whose string attribute claims
// 1.55 GB took 9 s and 1.6 GB to refuse). Refuses, as truncated or corrupt, a PNG whose chunks or
// an OpenEXR file whose header attributes do not lie within the file; other files pass unread.
// Returns the problem, or "" when the layout is plausible.
std::string imageLayoutProblem(const std::string& path);

}  // namespace solidtex::io::detail
