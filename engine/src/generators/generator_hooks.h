// What a video generator (command, comfyui) needs from whoever runs it: progress, log lines and
// a cancellation check, each optional. The plugins fill it from the host (plugins/common/
// generator_request.h); tests fill what they watch.
#pragma once

#include <functional>
#include <string>

namespace svgm {

struct GeneratorHooks {
  std::function<void(double fraction, const std::string& note)> progress;  // may be empty
  std::function<void(const std::string& line)> log;                        // may be empty
  std::function<void(const std::string& line)> warn;  // a warning the user sees; may be empty
  std::function<bool()> cancelled;                                         // may be empty
};

}  // namespace svgm
