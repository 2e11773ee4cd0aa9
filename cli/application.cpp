#include "cli/application.h"

#include <algorithm>
#include <exception>
#include <iostream>
#include <new>

#include "Version.h"
#include "cli/commandLine.h"
#include "cli/optionChecks.h"
#include "common/Error.h"
#include "common/OutputFiles.h"
#include "common/memoryBudget.h"
#include "parallel/Communicator.h"

namespace solidtex::cli {
namespace {

/// One line on stderr, as users' scripts expect from a failing command: from rank 0 alone when
/// mpirun started several processes, which all meet the same bad input.
int fail(const std::string& message, int code) {
  if (launchedAs().rank != 0) return code;
  std::string line = message;
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::cerr << "solidtex: error: " << line << '\n';
  return code;
}

}  // namespace

std::unique_ptr<Application> makeApplication(const std::string& commandLine) {
  auto application = std::make_unique<Application>();
  CLI::App& app = application->app;
  app.set_version_flag("--version", SOLIDTEX_VERSION);
  app.require_subcommand(1);
  application->actions = {
      {"analyze", addAnalyzeCommand(app)},
      {"particles", addParticlesCommand(app, commandLine)},
      {"compare", addCompareCommand(app)},
      {"synthesize", addSynthesizeCommand(app, commandLine)},
      {"synthesize2d", addSynthesize2dCommand(app)},
      {"spaciousness", addSpaciousnessCommand(app)},
      {"truth", addTruthCommand(app)},
  };
  for (CLI::App* command : app.get_subcommands({}))
    command->add_option_function<std::string>(
        "--max-memory",
        [](const std::string& size) {
          try {
            setMemoryLimit(parseMemorySize(size));
          } catch (const InputError& e) {
            throw CLI::ValidationError("--max-memory", e.what());
          }
        },
        "Refuse work that needs more memory than this (8G, 512M; default: what the system has free)");
  checkNumberTypes(app);
  return application;
}

std::string usageMessage(const CLI::App& app, const std::string& what) {
  const auto chosen = app.get_subcommands();
  return what + " (see solidtex " + (chosen.empty() ? "" : chosen.front()->get_name() + " ") + "--help)";
}

int runApplication(int argc, char** argv) {
  installInterruptHandlers();
  const auto application =
      makeApplication(volumeCommandLine({argv + std::min(argc, 1), argv + std::max(argc, 1)}));
  CLI::App& app = application->app;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(usageMessage(app, e.what()), kUsage);
  }
  try {
    const std::string command = app.get_subcommands().front()->get_name();
    if (command != "synthesize" && command != "particles") requireOneProcess(command);
    return application->actions.at(command)();
  } catch (const OptionError& e) {
    return fail(usageMessage(app, e.what()), kUsage);
  } catch (const std::bad_alloc&) {
    return fail("out of memory (see --max-memory; a smaller size needs less)", kFailed);
  } catch (const std::exception& e) {
    return fail(e.what(), kFailed);
  }
}

}  // namespace solidtex::cli
