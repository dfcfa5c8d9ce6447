#pragma once
// The InputError a call throws; a gtest failure when it throws none.
#include <gtest/gtest.h>

#include <functional>

#include "io/input_error.h"

namespace motostab::test {

using io::InputError;


inline InputError catchInputError(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError({}, "none");
}

}  // namespace motostab::test
