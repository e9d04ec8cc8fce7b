// Small wheels in sets (see wheel_sets.h).
#include "procedural/wheel_sets.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "procedural/part_rig_internal.h"
#include "scene/backdrop.h"

namespace svgm {

using part_rig_internal::path_box;
using part_rig_internal::round_path;

std::set<int> wheel_set_paths(const Scene& scene) {
  const size_t n = scene.paths.size();
  // The drawing's box, without its backdrops (a sky behind a car reaches the canvas' edges).
  RigBox drawing;
  std::vector<RigBox> box(n);
  for (size_t i = 0; i < n; ++i) {
    box[i] = path_box(scene.paths[i]);
    if (box[i].empty()) continue;
    const double pos = n > 1 ? static_cast<double>(i) / static_cast<double>(n) : 0;
    if (!is_backdrop(scene, {static_cast<int>(i)}, box[i].x0, box[i].y0, box[i].x1, box[i].y1, pos)) drawing.add(box[i]);
  }
  if (drawing.empty() || drawing.w() <= drawing.h()) return {};
  const double min_area = kSetWheelArea * scene.width * scene.height;
  const double low = drawing.y0 + kSetWheelLow * drawing.h();
  // Round paths low in the drawing, widest first, gathered by position (concentric rings).
  std::vector<int> round;
  for (size_t i = 0; i < n; ++i)
    if (!box[i].empty() && box[i].centre().y >= low && round_path(scene.paths[i], min_area)) round.push_back(static_cast<int>(i));
  std::stable_sort(round.begin(), round.end(), [&](int a, int b) { return box[a].w() > box[b].w(); });
  std::vector<std::vector<int>> positions;  // the first path of each is its widest
  for (int i : round) {
    bool joined = false;
    for (auto& p : positions) {
      const RigBox& w = box[p.front()];
      const Vec2 d = box[i].centre() - w.centre();
      if (std::hypot(d.x, d.y) <= kSetWheelConcentric * w.w()) {
        p.push_back(i);
        joined = true;
        break;
      }
    }
    if (!joined) positions.push_back({i});
  }
  // The largest set of positions alike in size and height; at least two, far enough apart.
  std::set<int> best;
  size_t best_count = 0;
  for (size_t a = 0; a < positions.size(); ++a) {
    const RigBox& A = box[positions[a].front()];
    std::vector<size_t> set;
    for (size_t b = 0; b < positions.size(); ++b) {
      const RigBox& B = box[positions[b].front()];
      const double rw = std::max(A.w(), B.w()) / std::max(std::min(A.w(), B.w()), 1e-9);
      if (rw <= kSetWheelSimilar && std::fabs(A.centre().y - B.centre().y) <= kSetWheelLevel * std::max(A.h(), B.h())) set.push_back(b);
    }
    if (set.size() < 2 || set.size() <= best_count) continue;
    double x0 = 1e300, x1 = -1e300;
    for (size_t b : set) {
      x0 = std::min(x0, box[positions[b].front()].centre().x);
      x1 = std::max(x1, box[positions[b].front()].centre().x);
    }
    if (x1 - x0 < kSetWheelSpread * drawing.w()) continue;
    best_count = set.size();
    best.clear();
    for (size_t b : set) best.insert(positions[b].begin(), positions[b].end());
  }
  return best;
}

}  // namespace svgm
