#pragma once
#include <string>

namespace solidtex {

/// Walks a .vdb's header, file metadata and grid descriptors before OpenVDB reads it, and throws
/// InputError naming the file for any length or offset that points past its end (a truncated or
/// damaged file). OpenVDB itself would allocate whatever a damaged length says: a "grid type" of
/// gigabytes, or memory until the system kills the process.
void checkVdbLayout(const std::string& path);

}  // namespace solidtex
