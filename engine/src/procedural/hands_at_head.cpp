// Hands drawn at the face (see hands_at_head.h).
#include "procedural/hands_at_head.h"

#include <algorithm>

namespace svgm {

namespace {

double overlap_area(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

bool inside(Vec2 p, const RigBox& b) { return p.x >= b.x0 && p.x <= b.x1 && p.y >= b.y0 && p.y <= b.y1; }

}  // namespace

std::vector<int> held_at_head(const std::vector<RigBox>& boxes, const std::vector<double>& areas,
                              const std::vector<RigBox>& arms) {
  const size_t n = boxes.size();
  std::vector<int> out(n, -1);
  if (n < 2 || arms.empty() || areas.size() != n) return out;
  const size_t face = static_cast<size_t>(std::max_element(areas.begin(), areas.end()) - areas.begin());
  const RigBox& fb = boxes[face];
  std::vector<char> beside(n, 0);
  for (size_t i = 0; i < n; ++i) beside[i] = i != face && !boxes[i].empty() && !inside(boxes[i].centre(), fb);
  for (size_t i = 0; i < n; ++i) {
    if (!beside[i]) continue;
    double best = overlap_area(boxes[i], fb);
    for (size_t a = 0; a < arms.size(); ++a)
      if (const double o = overlap_area(boxes[i], arms[a]); o > best) {
        best = o;
        out[i] = static_cast<int>(a);
      }
  }
  // A smaller path beside the face with its middle inside a held one's box goes with it.
  for (bool grew = true; grew;) {
    grew = false;
    for (size_t i = 0; i < n; ++i) {
      if (!beside[i] || out[i] >= 0) continue;
      for (size_t j = 0; j < n; ++j)
        if (out[j] >= 0 && areas[i] < areas[j] && inside(boxes[i].centre(), boxes[j])) {
          out[i] = out[j];
          grew = true;
          break;
        }
    }
  }
  return out;
}

}  // namespace svgm
