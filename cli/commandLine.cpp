#include "cli/commandLine.h"

#include <set>

namespace solidtex::cli {

std::string volumeCommandLine(const std::vector<std::string>& arguments) {
  const std::set<std::string> dropWithValue = {"-o",        "--output", "--threads",    "--report",
                                               "--preview", "--labels", "--plot",       "--tiff",
                                               "--npy",     "--vti",    "--max-memory", "--meshes"};
  std::string line = "solidtex";
  for (size_t i = 0; i < arguments.size(); ++i) {
    const std::string& arg = arguments[i];
    const std::string name = arg.substr(0, arg.find('='));
    if (arg.size() > 2 && arg.rfind("-o", 0) == 0 && arg[2] != '-') continue;  // -oPATH
    if (dropWithValue.count(name)) {
      i += name == arg ? 1 : 0;
      continue;
    }
    if (arg != "--quiet" && arg != "--no-quality") line += " " + arg;
  }
  return line;
}

}  // namespace solidtex::cli
