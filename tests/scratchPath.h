#pragma once
#include <filesystem>
#include <string>

namespace solidtex::test {

/// `name` in a folder of the system's temporary directory for `suite`, created if missing.
inline std::filesystem::path scratchPath(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("solidtex_" + suite);
  std::filesystem::create_directories(dir);
  return dir / name;
}

}  // namespace solidtex::test
