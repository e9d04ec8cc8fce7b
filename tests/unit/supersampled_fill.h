// Test-only: an independent rasteriser for filled cubic paths, so a test can draw a target
// without the engine's renderer (engine/src/raster and kernels/) and a bug shared by the renderer
// and the fitter cannot hide behind it. It shares no code with them: every cubic is flattened
// in double precision into many chords, and each pixel's coverage is the fraction of a 16 x 16
// grid of sample points inside the outline (scanline crossings, non-zero or even-odd rule).
// Paths are composited in order over white, colour times coverage times opacity ("over",
// straight colour), as the renderer's Rgba8 output on a white background is.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "svgmotion/png_io.h"
#include "svgmotion/scene.h"

namespace svgm::test {

// One outline to fill: closed polygons (pixel coordinates) and how to fill them.
struct FilledOutline {
  std::vector<std::vector<Vec2>> rings;  // each implicitly closed
  Rgba color;                            // straight colour, a = fill opacity
  float opacity = 1;
  FillRule rule = FillRule::NonZero;
};

// Chords per cubic: a 12 px circle quarter in 64 chords is off the curve by under 0.002 px.
constexpr int kChordsPerCubic = 64;
// Sample points per pixel side: coverage in steps of 1/256.
constexpr int kSamplesPerSide = 16;

// A subpath's cubics (points p0, then c1 c2 p3 per segment) as a closed polygon of chords, after
// `move` maps each control point; the closing edge back to p0 is a straight line (SVG's `Z`).
template <class Move>
std::vector<Vec2> flatten_closed(const Subpath& s, Move&& move) {
  std::vector<Vec2> ring;
  if (s.points.empty()) return ring;
  std::vector<Vec2> p(s.points.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = move(s.points[i]);
  ring.push_back(p[0]);
  for (size_t seg = 0; seg < s.segment_count(); ++seg) {
    const Vec2 a = p[3 * seg], b = p[3 * seg + 1], c = p[3 * seg + 2], d = p[3 * seg + 3];
    for (int j = 1; j <= kChordsPerCubic; ++j) {
      const double t = double(j) / kChordsPerCubic, u = 1 - t;
      const double wa = u * u * u, wb = 3 * u * u * t, wc = 3 * u * t * t, wd = t * t * t;
      ring.push_back({wa * a.x + wb * b.x + wc * c.x + wd * d.x, wa * a.y + wb * b.y + wc * c.y + wd * d.y});
    }
  }
  return ring;
}

// Fraction of each pixel's sample points inside the outline: width * height values in [0, 1].
inline std::vector<double> coverage(const FilledOutline& o, int width, int height) {
  std::vector<double> cov(static_cast<size_t>(width) * height, 0.0);
  const int sw = width * kSamplesPerSide;
  std::vector<std::pair<double, int>> crossings;  // x, winding direction
  for (int sy = 0; sy < height * kSamplesPerSide; ++sy) {
    const double y = (sy + 0.5) / kSamplesPerSide;  // sample centres
    crossings.clear();
    for (const auto& ring : o.rings)
      for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
        if ((a.y <= y) == (b.y <= y)) continue;  // half-open: a vertex on y counts once
        crossings.push_back({a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y), a.y < b.y ? 1 : -1});
      }
    std::sort(crossings.begin(), crossings.end());
    size_t next = 0;
    int winding = 0, inside_count = 0;
    for (int sx = 0; sx < sw; ++sx) {
      const double x = (sx + 0.5) / kSamplesPerSide;
      while (next < crossings.size() && crossings[next].first <= x) {
        winding += crossings[next].second;
        ++inside_count;
        ++next;
      }
      const bool inside = o.rule == FillRule::EvenOdd ? (inside_count % 2) != 0 : winding != 0;
      if (inside) cov[static_cast<size_t>(sy / kSamplesPerSide) * width + sx / kSamplesPerSide] += 1.0;
    }
  }
  for (double& c : cov) c /= kSamplesPerSide * kSamplesPerSide;
  return cov;
}

// The outlines composited in order over white, as an 8-bit RGBA image (opaque).
inline RgbaImage draw_over_white(const std::vector<FilledOutline>& outlines, int width, int height) {
  std::vector<double> rgb(static_cast<size_t>(width) * height * 3, 1.0);
  for (const auto& o : outlines) {
    const auto cov = coverage(o, width, height);
    const double col[3] = {o.color.r, o.color.g, o.color.b};
    for (size_t p = 0; p < cov.size(); ++p) {
      const double a = cov[p] * o.color.a * o.opacity;
      for (int ch = 0; ch < 3; ++ch) rgb[3 * p + ch] = col[ch] * a + rgb[3 * p + ch] * (1 - a);
    }
  }
  RgbaImage img{width, height, std::vector<uint8_t>(static_cast<size_t>(width) * height * 4, 255)};
  for (size_t p = 0; p < rgb.size() / 3; ++p)
    for (int ch = 0; ch < 3; ++ch)
      img.rgba[4 * p + ch] = static_cast<uint8_t>(std::lround(std::clamp(rgb[3 * p + ch], 0.0, 1.0) * 255));
  return img;
}

// The filled paths of a scene (no strokes: this rasteriser does not draw them), each control
// point mapped by move(path index, canvas point) to pixels.
template <class Move>
std::vector<FilledOutline> filled_outlines(const Scene& scene, Move&& move) {
  std::vector<FilledOutline> out;
  for (size_t i = 0; i < scene.paths.size(); ++i) {
    const Path& p = scene.paths[i];
    if (p.has_stroke) throw std::logic_error("supersampled_fill: strokes are not drawn");
    if (!p.has_fill) continue;
    FilledOutline o{{}, p.fill, p.opacity, p.fill_rule};
    for (const auto& s : p.subpaths)
      o.rings.push_back(flatten_closed(s, [&](Vec2 q) { return move(i, q); }));
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace svgm::test
