// The message of the svgm::Error a call throws, for tests that compare exact one-line errors;
// "(no error)" when it throws none.
#pragma once

#include <functional>
#include <string>

#include "svgmotion/error.h"

namespace svgm::test {

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace svgm::test
