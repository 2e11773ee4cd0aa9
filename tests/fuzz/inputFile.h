#pragma once
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace solidtex::fuzz {

/// The readers under test take a path, so each input goes through one file per process (fuzzing
/// jobs run side by side), in RAM where /dev/shm exists. The file is removed at exit.
class InputFile {
public:
  explicit InputFile(const std::string& name) {
    const std::filesystem::path shm = "/dev/shm";
    std::error_code ec;
    const auto dir = std::filesystem::is_directory(shm, ec) ? shm : std::filesystem::temp_directory_path();
    path_ = (dir / ("solidtex_fuzz_" + std::to_string(::getpid()) + "_" + name)).string();
  }
  ~InputFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// Replaces the file's contents with the input and returns its path.
  const std::string& write(const uint8_t* data, size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path_;
  }

private:
  std::string path_;
};

}  // namespace solidtex::fuzz
