#include <algorithm>
#include <exception>
#include <iostream>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "Version.h"
#include "cli/commandLine.h"
#include "cli/commands.h"

namespace {

/// One line on stderr, as users' scripts expect from a failing command.
int fail(const std::string& message, int code) {
  std::cerr << "solidtex: error: " << message << '\n';
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"solidtex: one photo of a material in, a 3D solid texture (OpenVDB) out"};
  app.set_version_flag("--version", SOLIDTEX_VERSION);
  app.require_subcommand(1);
  const std::string commandLine = solidtex::cli::volumeCommandLine({argv + std::min(argc, 1), argv + argc});
  const std::map<std::string, solidtex::cli::Action> actions = {
      {"analyze", solidtex::cli::addAnalyzeCommand(app)},
      {"particles", solidtex::cli::addParticlesCommand(app, commandLine)},
      {"compare", solidtex::cli::addCompareCommand(app)},
      {"synthesize", solidtex::cli::addSynthesizeCommand(app, commandLine)},
      {"synthesize2d", solidtex::cli::addSynthesize2dCommand(app)},
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
