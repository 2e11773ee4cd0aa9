#include "cli/optionChecks.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace solidtex::cli {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The value as a finite double, or nullopt-like NaN when it is not one.
double parsed(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || errno == ERANGE) return NAN;
  return value;
}

}  // namespace

CLI::Validator between(double low, double high) {
  const std::string range = "between " + number(low) + " and " + number(high);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const double value = parsed(text);
        if (std::isnan(value) || value < low || value > high)
          return "must be " + range + " (got " + text + ")";
        return {};
      },
      "in [" + number(low) + ", " + number(high) + "]");
}

CLI::Validator atLeast(double low) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const double value = parsed(text);
        if (std::isnan(value) || value < low)
          return "must be at least " + number(low) + " (got " + text + ")";
        return {};
      },
      "at least " + number(low));
}

CLI::Validator aboveAtMost(double low, double high) {
  const std::string range = "above " + number(low) + " and at most " + number(high);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const double value = parsed(text);
        if (std::isnan(value) || value <= low || value > high)
          return "must be " + range + " (got " + text + ")";
        return {};
      },
      "in (" + number(low) + ", " + number(high) + "]");
}

void checkNumberTypes(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& text) -> std::string {
        return std::isfinite(parsed(text)) ? std::string() : "must be a finite number (got " + text + ")";
      },
      "");
  const CLI::Validator unsignedWhole(
      [](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        if (digits) std::strtoull(text.c_str(), nullptr, 10);
        if (!digits || errno == ERANGE)
          return "must be a whole number from 0 to 18446744073709551615 (got " + text + ")";
        return {};
      },
      "");
  for (CLI::App* command : app.get_subcommands({})) {
    if (CLI::Option* threads = command->get_option_no_throw("--threads")) threads->check(atLeast(0));
    for (CLI::Option* option : command->get_options()) {
      const std::string type = option->get_type_name();
      if (type == "FLOAT") option->check(finite);
      if (type == "UINT") option->check(unsignedWhole);
    }
  }
}

}  // namespace solidtex::cli
