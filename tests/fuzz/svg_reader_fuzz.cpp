// Fuzz target: the whole SVG reader (XML, styles and <style> sheets, <use>, transforms, the
// viewBox, path data, SMIL <animate> at a time). Properties checked on every input:
//  - it returns a scene or throws svgm::Error, nothing else (no other exception, no crash, no
//    sanitizer report);
//  - the error is one line that starts with the file's name;
//  - every point of every path is finite and within SvgReadLimits::max_coordinate, every stroke
//    width finite, every colour and opacity in [0, 1]; the canvas size is finite and positive
//    (what the renderer and the fitter rely on);
//  - every warning is one line.
#include <cmath>
#include <string>
#include <string_view>

#include "fuzz_check.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"

namespace {

bool unit(float v) { return v >= 0 && v <= 1; }
bool unit(const svgm::Rgba& c) { return unit(c.r) && unit(c.g) && unit(c.b) && unit(c.a); }

void check_scene(const svgm::Scene& s, const svgm::SvgReadLimits& limits) {
  FUZZ_REQUIRE(std::isfinite(s.width) && std::isfinite(s.height) && s.width > 0 && s.height > 0,
               "canvas size finite and positive");
  FUZZ_REQUIRE(s.width <= limits.max_canvas_px && s.height <= limits.max_canvas_px,
               "canvas size within max_canvas_px");
  for (const auto& p : s.paths) {
    for (const auto& sp : p.subpaths) {
      FUZZ_REQUIRE(!sp.points.empty() && sp.points.size() % 3 == 1, "a subpath holds 1 + 3n points");
      for (const auto& q : sp.points)
        FUZZ_REQUIRE(std::fabs(q.x) <= limits.max_coordinate && std::fabs(q.y) <= limits.max_coordinate,
                     "coordinates finite and within max_coordinate");
    }
    FUZZ_REQUIRE(unit(p.fill) && unit(p.opacity), "fill colour and opacity in [0, 1]");
    if (p.has_stroke)
      FUZZ_REQUIRE(unit(p.stroke.color) && std::isfinite(p.stroke.width) && p.stroke.width >= 0 &&
                       p.stroke.width <= limits.max_coordinate && std::isfinite(p.stroke.miter_limit),
                   "stroke colour, width and miter limit");
    FUZZ_REQUIRE(p.group >= -1 && p.group < static_cast<int>(s.groups.size()), "group index in range");
  }
  for (const auto& g : s.groups)
    for (int i : g.paths) FUZZ_REQUIRE(i >= 0 && i < static_cast<int>(s.paths.size()), "group member in range");
  for (const auto& w : s.warnings) FUZZ_REQUIRE(svgm::fuzz::one_line(w), "a warning is one line");
}

void read_once(std::string_view text, const svgm::SvgReadLimits& limits) {
  static const std::string kName = "fuzz.svg";
  try {
    check_scene(svgm::read_svg_string(text, kName, limits), limits);
  } catch (const svgm::Error& e) {
    const std::string_view msg = e.what();
    FUZZ_REQUIRE(svgm::fuzz::one_line(msg), "an error is one line");
    FUZZ_REQUIRE(msg.rfind(kName + ": ", 0) == 0, "an error starts with the file name");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  svgm::SvgReadLimits limits;
  // The product's limits, but for the segment count: reaching 4 M segments through nested <use>
  // (tests/data/bad_input/svg/use_expansion.svg) is bounded work, 1.5 s natively, but under ASan
  // such inputs and their mutants brought the reader down to 13 executions per second. 32 K
  // keeps them refused by the same check, fast enough to fuzz everything else.
  limits.max_segments = 1u << 15;
  read_once(text, limits);
  // Animated documents are read again at a time, through the SMIL interpolation.
  if (text.find("<animate") != std::string_view::npos) {
    limits.animation_time = 0.37;
    read_once(text, limits);
  }
  return 0;
}
