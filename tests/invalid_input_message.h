// Test helper: the message of the InvalidInput that a call throws, empty when it throws none.
#pragma once

#include "geom/errors.h"

#include <string>

namespace clumpkit {

template <class Call>
std::string invalid_input_message(Call&& call) {
  try {
    call();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

}  // namespace clumpkit
