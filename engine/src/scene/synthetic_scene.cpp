// Procedural benchmark scenes (see synthetic_scene.h).
#include "scene/synthetic_scene.h"

#include <cmath>
#include <random>
#include <string>

namespace svgm {

Scene synthetic_blobs(int paths, double size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  Scene s;
  s.width = s.height = size;
  for (int i = 0; i < paths; ++i) {
    Path p;
    p.id = "blob" + std::to_string(i + 1);
    Subpath sp;
    sp.closed = true;
    const double r = size * (0.03 + 0.09 * U(rng));
    const double cx = r + (size - 2 * r) * U(rng), cy = r + (size - 2 * r) * U(rng);
    const int segs = 6;
    auto at = [&](double a, double rr) { return Vec2{cx + rr * std::cos(a), cy + rr * std::sin(a)}; };
    sp.points.push_back(at(0, r));
    for (int k = 1; k <= segs; ++k) {
      const double a0 = 2 * M_PI * (k - 1) / segs, a1 = 2 * M_PI * k / segs;
      const double bulge = r * (0.9 + 0.4 * U(rng));
      sp.points.push_back(at(a0 + 0.35, bulge));
      sp.points.push_back(at(a1 - 0.35, bulge));
      sp.points.push_back(at(a1, r));
    }
    p.subpaths.push_back(sp);
    p.fill = {static_cast<float>(U(rng)), static_cast<float>(U(rng)), static_cast<float>(U(rng)),
              U(rng) < 0.3 ? 0.7f : 1.0f};
    p.group = static_cast<int>(s.groups.size());
    s.groups.push_back({p.id, {i}});
    s.paths.push_back(std::move(p));
  }
  return s;
}

}  // namespace svgm
