// What every fuzz target shares: FUZZ_REQUIRE(condition, what) stops the run with a message
// when a property the parsers promise is broken, so libFuzzer records the input as a finding
// (a crash file) exactly as it does for a sanitizer report or an uncaught exception.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace svgm::fuzz {

[[noreturn]] inline void broken(const char* what, const char* file, int line) {
  std::fprintf(stderr, "fuzz property broken at %s:%d: %s\n", file, line, what);
  std::abort();
}

// An svgm::Error message is the one line a user sees: not empty and without line breaks.
inline bool one_line(std::string_view s) {
  return !s.empty() && s.find('\n') == std::string_view::npos && s.find('\r') == std::string_view::npos;
}

}  // namespace svgm::fuzz

#define FUZZ_REQUIRE(cond, what) \
  do {                           \
    if (!(cond)) ::svgm::fuzz::broken(what, __FILE__, __LINE__); \
  } while (0)
