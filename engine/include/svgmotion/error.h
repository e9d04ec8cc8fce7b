// The engine's error type: one exception class whose message is the one line a user sees.
//
// Inside the engine, failures throw svgm::Error with a message that already names the file (or
// device, or option) and the problem; front ends print it as "svgmotion: <message>" and exit
// non-zero. Plugins never let it cross their C boundary (see plugin.h when it exists).
#pragma once

#include <stdexcept>
#include <string>

namespace svgm {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace svgm
