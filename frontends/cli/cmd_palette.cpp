// `svgmotion palette N`: the N most distinct colours (white reserved for the background), one
// #rrggbb per line and nothing else on stdout. See engine/src/color/palette.h.
#include <charconv>
#include <cstdio>
#include <string>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "color/palette.h"
#include "svgmotion/error.h"

namespace svgm::cli {

int cmd_palette(const std::vector<std::string>& argv) {
  const std::vector<std::string> args = parse_args("palette", argv, {}, {}).positional;
  if (args.size() != 1) throw UsageError("palette: usage: svgmotion palette N");
  const std::string& s = args[0];
  int n = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
  if (s.empty() || s[0] < '0' || s[0] > '9' || ec != std::errc() || p != s.data() + s.size() ||
      n < 1 || n > kMaxPaletteSize)
    throw Error("palette: N must be an integer in 1.." + std::to_string(kMaxPaletteSize) + ", got '" +
                s + "'");
  std::string out;
  char line[16];
  for (const Rgb8& c : distinct_palette(n)) {
    std::snprintf(line, sizeof line, "#%02x%02x%02x\n", c.r, c.g, c.b);
    out += line;
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace svgm::cli
