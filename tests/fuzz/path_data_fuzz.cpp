// Fuzz target: SVG path data ("d") to cubic subpaths. Properties checked on every input:
//  - no crash and no sanitizer report (UBSan included: float-to-int conversions of huge arc
//    sweeps once were undefined);
//  - an error offset lies inside the text; every subpath holds 1 + 3n points;
//  - the cubic form is a fixed point: the output written back as "M p0 C c1 c2 p1 ... Z" (the
//    shortest round-tripping decimal of each coordinate) parses to exactly the same points, so
//    number scanning, implicit commands and Z handling agree with the writer.
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_check.h"
#include "svg/path_data.h"

namespace {

void put(std::string& s, double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  s += ' ';
  s.append(buf, end);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view d(reinterpret_cast<const char*>(data), size);
  std::vector<svgm::Subpath> out;
  const auto res = svgm::svg::parse_path_data(d, out);
  FUZZ_REQUIRE(res.ok || res.error_offset <= d.size(), "error offset inside the text");
  bool finite = true;
  for (const auto& sp : out) {
    FUZZ_REQUIRE(!sp.points.empty() && sp.points.size() % 3 == 1, "a subpath holds 1 + 3n points");
    for (const auto& p : sp.points) finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
  }
  if (!finite) return 0;  // overflowing geometry is the reader's to refuse (max_coordinate)

  std::string cubic;
  for (const auto& sp : out) {
    cubic += 'M';
    put(cubic, sp.points[0].x);
    put(cubic, sp.points[0].y);
    if (sp.points.size() > 1) cubic += " C";
    for (size_t i = 1; i < sp.points.size(); ++i) {
      put(cubic, sp.points[i].x);
      put(cubic, sp.points[i].y);
    }
    if (sp.closed) cubic += " Z";
    cubic += ' ';
  }
  std::vector<svgm::Subpath> again;
  const auto res2 = svgm::svg::parse_path_data(cubic, again);
  FUZZ_REQUIRE(res2.ok, "the written cubic form parses");
  FUZZ_REQUIRE(again.size() == out.size(), "the cubic form has the same subpaths");
  for (size_t i = 0; i < out.size(); ++i) {
    FUZZ_REQUIRE(again[i].closed == out[i].closed, "the cubic form keeps closedness");
    FUZZ_REQUIRE(again[i].points == out[i].points, "the cubic form has the same points");
  }
  return 0;
}
