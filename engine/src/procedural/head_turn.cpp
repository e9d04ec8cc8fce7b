// A head turned out of the picture's plane (see head_turn.h).
#include "procedural/head_turn.h"

#include <algorithm>
#include <cmath>

namespace svgm {

HeadAxis head_axis_of(const std::string& verb) {
  if (verb == "nod" || verb == "bow") return HeadAxis::Pitch;
  if (verb == "shake" || verb == "look" || verb == "spin") return HeadAxis::Yaw;
  return HeadAxis::Plane;
}

std::vector<HeadPath> head_paths(const RigBox& head, const std::vector<RigBox>& boxes) {
  std::vector<HeadPath> out(boxes.size());
  const Vec2 c = head.centre();
  const double rx = std::max(0.5 * head.w(), 1e-9), ry = std::max(0.5 * head.h(), 1e-9);
  for (size_t i = 0; i < boxes.size(); ++i) {
    const RigBox& b = boxes[i];
    out[i].middle = b.centre();
    if (b.empty() || b.area() > kFeatureShare * head.area()) continue;
    const double u = (b.centre().x - c.x) / rx, v = (b.centre().y - c.y) / ry;
    out[i].depth = std::sqrt(std::max(0.0, 1 - u * u - v * v));
  }
  return out;
}

Vec2 head_turn_point(const RigBox& head, Vec2 neck, HeadAxis axis, double degrees, const HeadPath& p, Vec2 q) {
  if (axis == HeadAxis::Plane || degrees == 0 || head.empty()) return q;
  const Vec2 c = head.centre();
  const double rx = 0.5 * head.w(), ry = 0.5 * head.h();
  const double th = degrees * M_PI / 180, cs = std::cos(th), sn = std::sin(th);
  if (p.depth > 0) {
    // The feature's middle turned on the ball (about its middle), the feature carried whole.
    if (axis == HeadAxis::Yaw) return {q.x + (p.middle.x - c.x) * (cs - 1) + p.depth * rx * sn, q.y};
    return {q.x, q.y + (p.middle.y - c.y) * (cs - 1) + p.depth * ry * sn};
  }
  // Hair hanging below the neck (behind the shoulders) is not on the ball: it stays (shortened
  // with the head, it slid up over openmoji 1F469-200D-1F9B1's shoulders: still share 0.29).
  if (axis == HeadAxis::Pitch) return {q.x, q.y < neck.y ? neck.y + (q.y - neck.y) * cs : q.y};
  // Yawing, the outline's points turn on the ball too (the face's outline slides across the hair
  // behind it), each by a depth that falls to nothing at the rim as smoothly as 1 - r^2: by the
  // ball's own depth, sqrt(1 - r^2), a handle beside the rim slid much farther than its end on it.
  const double u = (q.x - c.x) / std::max(rx, 1e-9), v = (q.y - c.y) / std::max(ry, 1e-9);
  return {c.x + (q.x - c.x) * cs + std::max(0.0, 1 - u * u - v * v) * rx * sn, q.y};
}

}  // namespace svgm
