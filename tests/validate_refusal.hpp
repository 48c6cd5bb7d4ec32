#pragma once
// The message of the ValueError an options struct's validate() throws ("" when it throws none),
// for the tests that check every refusal names its field.
#include <string>

#include "fspm/error.hpp"

namespace fspm::test_support {

template <typename Options>
std::string refusal(const Options& options) {
  try {
    options.validate();
  } catch (const ValueError& e) {
    return e.what();
  }
  return {};
}

}  // namespace fspm::test_support
