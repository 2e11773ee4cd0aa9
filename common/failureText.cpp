#include "common/failureText.h"

#include <new>
#include <stdexcept>

#include "common/Error.h"

namespace solidtex {

std::string failureText(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const OptionError& e) {
    return std::string("2") + e.what();
  } catch (const std::bad_alloc&) {
    return "1out of memory (see --max-memory; smaller bricks need less)";
  } catch (const std::exception& e) {
    return std::string("1") + e.what();
  }
}

void throwFailureText(const std::string& text) {
  if (text.empty()) throw std::logic_error("throwFailureText: no failure");
  if (text.front() == '2') throw OptionError(text.substr(1));
  throw InputError(text.substr(1));
}

}  // namespace solidtex
