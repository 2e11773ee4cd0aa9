#pragma once
/// @file failureText.h
/// @brief A failure as one line of text that another process can throw again: the bricked runs'
/// processes agree on the first failure instead of leaving the others waiting.
#include <exception>
#include <string>

namespace solidtex {

/// The exception as text: its kind ('2' for OptionError, '1' for any other), then its message.
std::string failureText(const std::exception_ptr& failure);

/// Throws what failureText described: OptionError or InputError, with its message.
[[noreturn]] void throwFailureText(const std::string& text);

}  // namespace solidtex
