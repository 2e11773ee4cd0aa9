#pragma once
/// @file optionChecks.h
/// @brief Checks on option values that say in words what is wrong.
#include <CLI/CLI.hpp>

namespace solidtex::cli {

/// A number in [low, high]: "must be between 0 and 64 (got 1e+09)".
CLI::Validator between(double low, double high);

/// A number of at least `low`: "must be at least 0 (got -1)".
CLI::Validator atLeast(double low);

/// A number above `low` and at most `high`: "must be above 0 and at most 64 (got 0)".
CLI::Validator aboveAtMost(double low, double high);

/// Adds to every option of `app`'s subcommands what its type needs and the parser does not check:
/// a real number must be finite (nan, inf refused); an unsigned whole number must not be negative
/// and must fit (a seed of -1 or 2^64 is refused instead of wrapping to 2^64 - 1); --threads must not be
/// negative.
void checkNumberTypes(CLI::App& app);

}  // namespace solidtex::cli
