#include <gtest/gtest.h>

#include <new>
#include <stdexcept>

#include "common/Error.h"
#include "common/failureText.h"

namespace solidtex {
namespace {

template <typename Thrown>
std::string textOf(const Thrown& thrown) {
  return failureText(std::make_exception_ptr(thrown));
}

// Options refused stay options refused in another process (exit code 2); every other failure is
// a failed job (1), with its line.
TEST(FailureText, KeepsTheKindAndTheLine) {
  EXPECT_THROW(throwFailureText(textOf(OptionError("--bricks too small"))), OptionError);
  EXPECT_THROW(throwFailureText(textOf(InputError("no such photo"))), InputError);
  EXPECT_THROW(throwFailureText(textOf(std::runtime_error("disk full"))), InputError);
  try {
    throwFailureText(textOf(std::bad_alloc()));
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("out of memory", 0), 0u);
  }
  try {
    throwFailureText(textOf(OptionError("--bricks too small")));
  } catch (const OptionError& e) {
    EXPECT_STREQ(e.what(), "--bricks too small");
  }
  EXPECT_THROW(throwFailureText(""), std::logic_error);
}

}  // namespace
}  // namespace solidtex
