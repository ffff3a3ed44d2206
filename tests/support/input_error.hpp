#pragma once
// The message of the InputError that `read` throws, for tests of bad input;
// when it throws none, a test failure that shows `what` was accepted.
#include <gtest/gtest.h>

#include <string>

#include "mesh/errors.hpp"

namespace tetsmooth::testing {

template <class Read>
std::string input_error_message(Read&& read, const std::string& what) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << what;
  return "";
}

}  // namespace tetsmooth::testing
