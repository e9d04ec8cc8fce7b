// Mapping false-colour candidate frames back to the drawing's colours (see
// user_colours.h).
#include "report/user_colours.h"

#include <algorithm>
#include <cmath>

#include "color/palette_json.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"

namespace svgm {

std::optional<ColourMap> user_colour_map(const std::filesystem::path &run,
                                         std::string &why_not) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(run / "palette.json", ec)) {
    why_not = "no palette.json (the recolorer has not run)";
    return std::nullopt;
  }
  ColourMap m;
  try {
    const auto palette = read_palette(run / "palette.json");
    const Scene s = read_svg_file(run / "grouped.svg");
    for (const Path &p : s.paths) {
      const auto it = palette.find(p.id);
      if (it == palette.end() || !(p.has_fill || p.has_stroke))
        continue;
      m.from.push_back(it->second);
      m.to.push_back(p.has_fill ? p.fill : p.stroke.color);
    }
  } catch (const Error &e) {
    why_not = e.what();
    return std::nullopt;
  }
  if (m.from.empty()) {
    why_not = "palette.json names no part of grouped.svg";
    return std::nullopt;
  }
  return m;
}

void to_user_colours(RgbaImage &img, const ColourMap &map) {
  const size_t n =
      static_cast<size_t>(img.width) * static_cast<size_t>(img.height);
  std::vector<int> label(n, 0);
  std::vector<float> share(n, 0);
  for (size_t p = 0; p < n; ++p) {
    const uint8_t *px8 = &img.rgba[4 * p];
    const float q[3] = {px8[0] / 255.f - 1, px8[1] / 255.f - 1,
                        px8[2] / 255.f - 1}; // pixel - white
    // The palette colour c and the share a of it whose mix with white, white +
    // a (c - white), is nearest the pixel.
    float best = INFINITY;
    for (size_t i = 0; i < map.from.size(); ++i) {
      const float c[3] = {map.from[i].r - 1, map.from[i].g - 1,
                          map.from[i].b - 1};
      const float cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
      const float a =
          cc > 1e-6f
              ? std::clamp((q[0] * c[0] + q[1] * c[1] + q[2] * c[2]) / cc, 0.f,
                           1.f)
              : 1.f;
      // A part's colour half mixed with white can be another part's colour (the
      // man's red belt at half is his pink face): a mix costs kMixCost per unit
      // of white in it, so a whole colour that fits wins and only edges (no
      // whole colour near them) read as mixes.
      constexpr float kMixCost = 0.01f; // squared RGB distance in [0, 1] units;
                                        // belt vs face: 0.0002 vs 0.0004
      float d = kMixCost * (1 - a);
      for (int k = 0; k < 3; ++k)
        d += (q[k] - a * c[k]) * (q[k] - a * c[k]);
      if (d < best)
        best = d, share[p] = a, label[p] = static_cast<int>(i);
    }
  }
  // Codec noise (chroma at a quarter of the resolution) flips single pixels
  // between palette colours of similar brightness: each pixel takes the part
  // most of its 3x3 neighbourhood (weighted by their shares) belongs to.
  std::vector<float> votes(map.from.size());
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      std::fill(votes.begin(), votes.end(), 0.f);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= img.width || yy >= img.height)
            continue;
          const size_t q =
              static_cast<size_t>(yy) * static_cast<size_t>(img.width) +
              static_cast<size_t>(xx);
          votes[static_cast<size_t>(label[q])] += share[q];
        }
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(img.width) +
                       static_cast<size_t>(x);
      const size_t i = static_cast<size_t>(
          std::max_element(votes.begin(), votes.end()) - votes.begin());
      const Rgba &u = map.to[i];
      const float a = share[p] * u.a;
      const float out[3] = {1 - a * (1 - u.r), 1 - a * (1 - u.g),
                            1 - a * (1 - u.b)};
      for (int k = 0; k < 3; ++k)
        img.rgba[4 * p + static_cast<size_t>(k)] = static_cast<uint8_t>(
            std::lround(255 * std::clamp(out[k], 0.f, 1.f)));
    }
}

} // namespace svgm
