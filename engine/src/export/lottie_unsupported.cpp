// The Lottie export's one warning of what it cannot express (see lottie_unsupported.h).
#include "export/lottie_unsupported.h"

#include <string_view>

namespace svgm::lottie {

namespace {

// Reader warnings (svg_reader.cpp: "<file>: <element> [and N more elements]: <what>") whose
// content the Lottie file does not draw, and the name each gets in the line.
struct Unsupported {
  std::string_view what, name;
};
constexpr Unsupported kReaderSkips[] = {
    {"filter ignored", "filter"},
    {"pattern paint not supported", "pattern paint"},
    {"markers ignored", "markers"},
    {"text is not supported", "text"},
    {"images are not supported", "image"},
    {"foreignObject is not supported", "foreignObject"},
};

}  // namespace

std::string cannot_express_line(const Scene& scene, const std::vector<std::string>& approximate) {
  std::vector<std::string> items;
  for (const std::string& w : scene.warnings) {
    for (const Unsupported& u : kReaderSkips) {
      const size_t at = w.find(u.what);
      const size_t open = w.find(": <");
      if (at == std::string::npos || open == std::string::npos || open > at) continue;
      const size_t close = w.rfind(": ", at);
      std::string element = w.substr(open + 2, close - open - 2);
      items.push_back(std::string(u.name) + " on " + element);
      break;
    }
  }
  for (const std::string& a : approximate) {
    bool seen = false;
    for (const std::string& i : items) seen = seen || i == a;
    if (!seen) items.push_back(a);
  }
  if (items.empty()) return {};
  std::string line = "cannot express in Lottie: ";
  for (size_t i = 0; i < items.size(); ++i) line += (i ? ", " : "") + items[i];
  return line;
}

}  // namespace svgm::lottie
