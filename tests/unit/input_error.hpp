// The message of the InputError a call throws: what the tests of strict readers look for.
#pragma once

#include <string>

#include "common/errors.hpp"

namespace arg {

// e.what() of the InputError that f() throws, or `none` when it throws none.
template <class F>
std::string input_error_of(F&& f, const std::string& none = "(no InputError)") {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return none;
}

}  // namespace arg
