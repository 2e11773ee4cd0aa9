// The command line: the input split on NUL bytes is argv[1..], parsed by the real application's
// CLI11 parser. Only the parse runs, never the chosen subcommand's action. A CLI::ParseError
// (including --help and --version, which CLI11 reports as exceptions) is the parser refusing or
// answering; anything else escaping parse() would escape runApplication too and end the process.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cli/application.h"
#include "cli/commandLine.h"
#include "common/memoryBudget.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> arguments;
  if (size > 0) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (std::size_t start = 0;;) {
      const std::size_t end = text.find('\0', start);
      arguments.push_back(text.substr(start, end - start));
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  std::vector<const char*> argv{"solidtex"};
  for (const auto& argument : arguments) argv.push_back(argument.c_str());

  const auto application = solidtex::cli::makeApplication(solidtex::cli::volumeCommandLine(arguments));
  try {
    application->app.parse(int(argv.size()), argv.data());
  } catch (const CLI::ParseError&) {
  }
  solidtex::setMemoryLimit(0);  // --max-memory sets a process-wide cap; each input starts without one
  return 0;
}
