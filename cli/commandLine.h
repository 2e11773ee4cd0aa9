#pragma once
/// @file commandLine.h
/// @brief The command line a volume records in its metadata.
#include <string>
#include <vector>

namespace solidtex::cli {

/// "solidtex" followed by the arguments that decide the volume (argv[1..]). Where the outputs go
/// (-o, --report, --preview, --labels, --plot, --tiff, --npy, --vti), how many threads and how much memory
/// made them, --quiet and --no-quality are left out, so that the same volume made elsewhere is the same
/// bytes.
std::string volumeCommandLine(const std::vector<std::string>& arguments);

}  // namespace solidtex::cli
