// The pieces of Lottie JSON that every part of the Lottie export writes: a text buffer that
// writes numbers with exactly the decimals asked for (the file's size is mostly these numbers),
// a bezier shape, a static colour, and SVG's caps and joins as Lottie's codes. Shared by the
// writer (lottie_writer.cpp), the paint servers (lottie_paint.h) and the compositing layers
// (lottie_compositing.h).
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "export/keyframe_reduce.h"
#include "svgmotion/scene.h"

namespace svgm::lottie {

// Colours are written to 1/10000 (far below one 8-bit level), opacities (0..100) to 1/100,
// frame times to 1/1000 of a frame.
inline constexpr double kColourScale = 1e4, kOpacityScale = 1e2, kFrameScale = 1e3;
// Two on-curve points this close (canvas pixels) are the same point: a closed subpath that
// returns exactly to its start is written without the zero-length closing segment.
inline constexpr double kSamePoint = 1e-9;

class JsonText {
 public:
  explicit JsonText(int decimals) : coord_scale_(std::pow(10.0, decimals)) {}
  JsonText& raw(std::string_view t) {
    s_ += t;
    return *this;
  }
  JsonText& num(double v, double scale);
  JsonText& coord(double v) { return num(v, coord_scale_); }
  JsonText& str(const std::string& t);
  // {"a":0,"k":v}
  JsonText& fixed(double v, double scale) {
    raw("{\"a\":0,\"k\":");
    num(v, scale);
    return raw("}");
  }
  // [x,y] in coordinates' precision
  JsonText& pair(double x, double y) { return raw("[").coord(x).raw(",").coord(y).raw("]"); }
  double coord_scale() const { return coord_scale_; }
  // The compact export measures each layer's decimals (compact_motion.h).
  void set_decimals(int decimals) { coord_scale_ = std::pow(10.0, decimals); }
  std::string& text() { return s_; }

 private:
  std::string s_;
  double coord_scale_;
};

// The identity transform of a layer after its opacity, and a group's: the players' and the
// lottie-spec's defaults (rotation 0, position and anchor 0, scale 100 %, no skew) are not
// written, which lottie-web, librlottie and ThorVG read alike; the man's 22 layers wrote 5 kB
// of identities (with ddd, sr and ao at their defaults). A group's opacity stays: lottie-web
// draws nothing of a shape group whose `tr` has no `o`.
inline constexpr std::string_view kLayerTransformAfterOpacity = "}";
inline constexpr std::string_view kGroupTransform = "{\"ty\":\"tr\",\"o\":{\"a\":0,\"k\":100}}";

// One subpath's control points {p0, c1, c2, p1, ...} (x, y pairs) as a Lottie bezier: vertices
// with in and out tangents relative to them. A closed subpath ends on its start (the reader
// adds the closing line); `merge_close` drops that last vertex, folding its in-tangent into
// the first.
void write_bezier(JsonText& j, const double* p, size_t n_points, bool closed, bool merge_close);

// Whether a closed subpath's last point is its first (write_bezier's merge_close).
bool returns_to_start(const double* p, size_t n_points, bool closed);

// A keyframe's easing towards the next (keyframe_reduce.h): "o" is the curve's first handle,
// "i" its second; linear as (0,0) and (1,1), as SMIL's calcMode="linear".
void write_easing(JsonText& j, const Easing& e);

// A property over the written values, static ({"a":0,"k":value(0)}) or keyframed at `frames`
// (one per value): every value, linear in time, when `keys` is null, else only the kept ones
// with their easing. `value(i)` writes value i; a one-dimensional keyframe value is written as
// an array ("s":[v]) when `scalar`: lottie-web reads a bare number there as no value.
template <typename Write>
void write_property(JsonText& j, const std::vector<double>& frames, size_t n, Write&& value, bool animated,
                    bool scalar = false, const ReducedKeys* keys = nullptr) {
  if (!animated) {
    j.raw("{\"a\":0,\"k\":");
    value(0);
    j.raw("}");
    return;
  }
  const size_t count = keys ? keys->keys.size() : n;
  j.raw("{\"a\":1,\"k\":[");
  for (size_t k = 0; k < count; ++k) {
    const size_t i = keys ? keys->keys[k] : k;
    if (k) j.raw(",");
    j.raw("{\"t\":").num(frames[i], kFrameScale).raw(",\"s\":").raw(scalar ? "[" : "");
    value(i);
    j.raw(scalar ? "]" : "");
    if (k + 1 < count) write_easing(j, keys ? keys->easing[k] : Easing{});
    j.raw("}");
  }
  j.raw("]}");
}

// {"a":0,"k":[r,g,b,1]}
void write_colour(JsonText& j, const Rgba& c);

int lottie_cap(LineCap c);
// Lottie has miter (with a limit), round and bevel; SVG 2's miter-clip is written as miter.
int lottie_join(LineJoin c);

}  // namespace svgm::lottie
