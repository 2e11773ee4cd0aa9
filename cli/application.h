#pragma once
/// @file application.h
/// @brief The whole command line: every subcommand with its options, and the exit-code policy.
#include <map>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.h"

namespace solidtex::cli {

/// Exit codes: 0 success, 1 the command failed (bad input, an output it cannot write, not enough
/// memory), 2 the command line is wrong (unknown option, a value out of range), 128 + the signal's
/// number when interrupted (130 SIGINT, 143 SIGTERM, 129 SIGHUP).
enum ExitCode : int { kSuccess = 0, kFailed = 1, kUsage = 2 };

/// The parser and what each subcommand runs once parsing succeeded.
struct Application {
  CLI::App app{"solidtex: one photo of a material in, a 3D solid texture (OpenVDB) out"};
  std::map<std::string, Action> actions;
};

/// Builds the parser; `commandLine` is what volumes record (volumeCommandLine).
std::unique_ptr<Application> makeApplication(const std::string& commandLine);

/// What the command line says for a wrong command line: `what` and where to look for help.
std::string usageMessage(const CLI::App& app, const std::string& what);

/// Parses argv and runs the chosen subcommand: the exit code, with one `solidtex: error:` line on
/// stderr for any failure.
int runApplication(int argc, char** argv);

}  // namespace solidtex::cli
