#include <exception>
#include <iostream>
#include <map>
#include <set>
#include <string>

#include <CLI/CLI.hpp>

#include "Version.h"
#include "cli/commands.h"

namespace {

/// The arguments that decide the volume, for its metadata: where the outputs go and how many
/// threads made them are left out, so that the same volume is the same bytes.
std::string joinArguments(int argc, char** argv) {
  const std::set<std::string> dropWithValue = {"-o", "--output", "--threads", "--report", "--preview", "--labels", "--plot"};
  std::string line = "solidtex";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::string name = arg.substr(0, arg.find('='));
    if (arg.size() > 2 && arg.rfind("-o", 0) == 0 && arg[2] != '-') continue;  // -oPATH
    if (dropWithValue.count(name)) {
      i += name == arg ? 1 : 0;
      continue;
    }
    if (arg != "--quiet") line += " " + arg;
  }
  return line;
}

/// One line on stderr, as users' scripts expect from a failing command.
int fail(const std::string& message, int code) {
  std::cerr << "solidtex: error: " << message << '\n';
  return code;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{"solidtex: one photo of a material in, a 3D solid texture (OpenVDB) out"};
  app.set_version_flag("--version", SOLIDTEX_VERSION);
  app.require_subcommand(1);
  const std::string commandLine = joinArguments(argc, argv);
  const std::map<std::string, solidtex::cli::Action> actions = {
      {"analyze", solidtex::cli::addAnalyzeCommand(app)},
      {"particles", solidtex::cli::addParticlesCommand(app, commandLine)},
      {"compare", solidtex::cli::addCompareCommand(app)},
      {"synthesize", solidtex::cli::addSynthesizeCommand(app, commandLine)},
      {"spaciousness", solidtex::cli::addSpaciousnessCommand(app)},
      {"truth", solidtex::cli::addTruthCommand(app)},
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(std::string(e.what()) + " (see solidtex --help)", 2);
  }
  try {
    return actions.at(app.get_subcommands().front()->get_name())();
  } catch (const std::exception& e) {
    return fail(e.what(), 1);
  }
}
