// Lottie JSON pieces (see lottie_json.h).
#include "export/lottie_json.h"

#include <nlohmann/json.hpp>

#include "svg/svg_number.h"
#include "svgmotion/utf8_text.h"

namespace svgm::lottie {

JsonText& JsonText::num(double v, double scale) {
  svg::append_rounded(s_, v, scale);
  return *this;
}

JsonText& JsonText::str(const std::string& t) { return raw(json_text(nlohmann::json(t))); }

void write_bezier(JsonText& j, const double* p, size_t n_points, bool closed, bool merge_close) {
  const size_t n = (n_points - 1) / 3;  // segments
  const size_t nv = merge_close ? n : n + 1;
  auto x = [&](size_t i) { return p[2 * i]; };
  auto y = [&](size_t i) { return p[2 * i + 1]; };
  j.raw("{\"i\":[");
  for (size_t v = 0; v < nv; ++v) {
    if (v) j.raw(",");
    const size_t at = 3 * v;
    if (v > 0) j.pair(x(at - 1) - x(at), y(at - 1) - y(at));
    else if (merge_close) j.pair(x(3 * n - 1) - x(0), y(3 * n - 1) - y(0));
    else j.pair(0, 0);
  }
  j.raw("],\"o\":[");
  for (size_t v = 0; v < nv; ++v) {
    if (v) j.raw(",");
    const size_t at = 3 * v;
    if (v < n) j.pair(x(at + 1) - x(at), y(at + 1) - y(at));
    else j.pair(0, 0);
  }
  j.raw("],\"v\":[");
  for (size_t v = 0; v < nv; ++v) {
    if (v) j.raw(",");
    j.pair(x(3 * v), y(3 * v));
  }
  j.raw("],\"c\":").raw(closed ? "true" : "false").raw("}");
}

bool returns_to_start(const double* p, size_t n_points, bool closed) {
  const size_t n = (n_points - 1) / 3;
  return closed && n >= 2 && std::fabs(p[6 * n] - p[0]) <= kSamePoint && std::fabs(p[6 * n + 1] - p[1]) <= kSamePoint;
}

void write_easing(JsonText& j, const Easing& e) {
  if (e.is_linear()) {
    j.raw(",\"i\":{\"x\":1,\"y\":1},\"o\":{\"x\":0,\"y\":0}");
    return;
  }
  j.raw(",\"i\":{\"x\":0.6667,\"y\":").num(e.y2, 1e4).raw("},\"o\":{\"x\":0.3333,\"y\":").num(e.y1, 1e4).raw("}");
}

void write_colour(JsonText& j, const Rgba& c) {
  j.raw("{\"a\":0,\"k\":[").num(c.r, kColourScale).raw(",").num(c.g, kColourScale).raw(",");
  j.num(c.b, kColourScale).raw(",1]}");
}

int lottie_cap(LineCap c) {
  switch (c) {
    case LineCap::Butt: return 1;
    case LineCap::Round: return 2;
    case LineCap::Square: return 3;
  }
  return 1;
}

int lottie_join(LineJoin c) {
  switch (c) {
    case LineJoin::Miter:
    case LineJoin::MiterClip: return 1;
    case LineJoin::Round: return 2;
    case LineJoin::Bevel: return 3;
  }
  return 1;
}

}  // namespace svgm::lottie
