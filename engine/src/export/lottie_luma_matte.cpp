// A luminance mask's content as alpha-matte content (see lottie_luma_matte.h).
#include "export/lottie_luma_matte.h"

#include <algorithm>
#include <cmath>

namespace svgm::lottie {

namespace {

// Rec. 709 luminance of sRGB values, as the mask's render takes it (raster/layer_compositor.cpp).
double luminance(const Rgba& c) { return 0.2125 * c.r + 0.7154 * c.g + 0.0721 * c.b; }

// Below this, a colour's luminance is taken as black: the mask value it gives is under half a
// level of an 8-bit channel.
constexpr double kBlack = 0.5 / 255;

Rgba white(double alpha) { return {1, 1, 1, static_cast<float>(std::clamp(alpha, 0.0, 1.0))}; }

// `g` with white stops whose alpha is L(c) a (`lum`) or a, and stops added where L(c) a is
// quadratic (both change) until linear alpha is within 1/512 of it.
Gradient white_gradient(const Gradient& g, bool lum) {
  Gradient w = g;
  w.stops.clear();
  const auto alpha = [lum](const Rgba& c, double a) { return lum ? luminance(c) * a : a; };
  for (size_t i = 0; i < g.stops.size(); ++i) {
    const GradientStop& s = g.stops[i];
    if (i > 0 && lum) {
      const GradientStop& p = g.stops[i - 1];
      // L(c(u)) a(u) minus its chord is -dL da u (1 - u), at most |dL da| / 4 at u = 1/2; with
      // k pieces the chords are within |dL da| / (4 k^2).
      const double dl = luminance(s.color) - luminance(p.color), da = s.color.a - p.color.a;
      const int k = std::clamp(static_cast<int>(std::ceil(std::sqrt(128.0 * std::fabs(dl * da)))), 1, 16);
      for (int j = 1; j < k; ++j) {
        const float u = static_cast<float>(j) / static_cast<float>(k);
        const Rgba c = {p.color.r + u * (s.color.r - p.color.r), p.color.g + u * (s.color.g - p.color.g),
                        p.color.b + u * (s.color.b - p.color.b), p.color.a + u * (s.color.a - p.color.a)};
        w.stops.push_back({p.offset + u * (s.offset - p.offset), white(alpha(c, c.a))});
      }
    }
    w.stops.push_back({s.offset, white(alpha(s.color, s.color.a))});
  }
  return w;
}

// Whether every colour the path paints has a luminance below kBlack (`black`) or above 1 - kBlack.
bool paints_only(const Path& p, const std::vector<Gradient>& gradients, bool black) {
  const auto ok = [black](const Rgba& c) { return black ? luminance(c) < kBlack : luminance(c) > 1 - kBlack; };
  const auto paint_ok = [&](bool has, const Rgba& c, int g) {
    if (!has) return true;
    if (g < 0) return ok(c);
    const auto& stops = gradients[static_cast<size_t>(g)].stops;
    return std::all_of(stops.begin(), stops.end(), [&](const GradientStop& s) { return ok(s.color); });
  };
  return paint_ok(p.has_fill, p.fill, p.fill_gradient) && paint_ok(p.has_stroke, p.stroke.color, p.stroke_gradient);
}

// The path's box in canvas space, its stroke's reach included.
struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  bool meets(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

Box box_of(const Path& p) {
  Box b;
  for (const Subpath& sp : p.subpaths)
    for (const Vec2& q : sp.points) {
      b.x0 = std::min(b.x0, q.x), b.y0 = std::min(b.y0, q.y);
      b.x1 = std::max(b.x1, q.x), b.y1 = std::max(b.y1, q.y);
    }
  const double h = p.has_stroke ? 0.5 * p.stroke.width * std::max(1.0, p.stroke.miter_limit) : 0;
  return {b.x0 - h, b.y0 - h, b.x1 + h, b.y1 + h};
}

}  // namespace

AlphaMatteContent luminance_as_alpha(const Mask& mask, const std::vector<Gradient>& gradients) {
  AlphaMatteContent out;
  std::vector<Box> below;  // the boxes of the paths drawn so far
  for (const Path& src : mask.paths) {
    const Box box = box_of(src);
    const bool over = std::any_of(below.begin(), below.end(), [&](const Box& b) { return b.meets(box); });
    below.push_back(box);
    // A black path outside any inner layer cuts what lies below it with its own alpha; inside
    // one, that layer's opacity would fade the cut too, so it stays an (approximate) white path.
    const bool cut = over && src.layer < 0 && paints_only(src, gradients, true);
    if (over && !cut && !paints_only(src, gradients, false)) out.exact = false;
    // The cut's matte is the path's alpha; any other path paints white at L a.
    Path p = src;
    const auto whiten = [&](bool has, Rgba& color, int& gradient) {
      if (!has) return;
      if (gradient >= 0) {
        out.gradients.push_back(white_gradient(gradients[static_cast<size_t>(gradient)], !cut));
        gradient = static_cast<int>(out.gradients.size()) - 1;
      }
      color = white(cut ? color.a : luminance(color) * color.a);
    };
    whiten(p.has_fill, p.fill, p.fill_gradient);
    whiten(p.has_stroke, p.stroke.color, p.stroke_gradient);
    out.paths.push_back(std::move(p));
    out.cut.push_back(cut);
  }
  return out;
}

}  // namespace svgm::lottie
