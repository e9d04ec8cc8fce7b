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

// A run that worked but whose result must not be trusted: the fit failed its quality gate, or
// every candidate video was flagged. Front ends exit with `exit_status()` (documented in the
// README: 3 = the fit was rejected, 4 = every candidate video was flagged) instead of 1, so a
// script can tell "broken input" from "no usable result".
class Rejected : public Error {
 public:
  static constexpr int kFitRejected = 3;
  static constexpr int kCandidatesFlagged = 4;
  Rejected(const std::string& message, int exit_status) : Error(message), status_(exit_status) {}
  int exit_status() const { return status_; }

 private:
  int status_;
};

}  // namespace svgm
