// What a turning wheel carries (see wheel_riders.h).
#include "procedural/wheel_riders.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace svgm {

namespace {

// A ring is centred on the wheel when its box's centre is within this share of the wheel's
// width from the wheel's (a ferris wheel's outer rim, drawn a little larger than the ring
// that was found round, is off by 1.7 % of the width).
constexpr double kRingConcentric = 0.1;

double overlap_area(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return ox > 0 && oy > 0 ? ox * oy : 0;
}

}  // namespace

bool turns_with_wheel(const RigBox& box, const std::vector<Vec2>& pts, const RigBox& wheel) {
  if (pts.empty() || wheel.empty()) return false;
  const Vec2 c = wheel.centre();
  const double R = 0.5 * wheel.w();
  double nearest = 1e300;
  for (const Vec2& q : pts) {
    const double r = std::hypot(q.x - c.x, q.y - c.y);
    if (r > (1 + kWheelInsidePad) * R) return false;
    nearest = std::min(nearest, r);
  }
  const Vec2 d = box.centre() - c;
  return nearest <= kRimShare * R || std::hypot(d.x, d.y) <= kRingConcentric * wheel.w();
}

bool rides_wheel(const RigBox& part, const RigBox& wheel) {
  if (part.empty() || wheel.empty()) return false;
  const Vec2 d = part.centre() - wheel.centre();
  const double r = std::hypot(d.x, d.y), R = 0.5 * wheel.w();
  // A part with no area (a straight stroke's box) lies "90 % inside" anything: only its
  // distance counts (a sketched handlebar rode round a wheel it crossed nowhere).
  return part.area() <= kRideMaxArea * wheel.area() && r >= kRimShare * R &&
         (r <= kRideReach * R || (part.area() > 0 && overlap_area(part, wheel) >= 0.9 * part.area()));
}

std::vector<char> in_rider_sets(const std::vector<RigBox>& boxes) {
  auto ratio = [](double a, double b) { return std::max(a, b) / std::max(std::min(a, b), 1e-9); };
  std::vector<char> out(boxes.size(), 1);
  if (boxes.size() < static_cast<size_t>(kMinSymmetricRiders)) return out;  // a lone cabin or two ride
  for (size_t i = 0; i < boxes.size(); ++i) {
    int alike = 0;
    for (size_t j = 0; j < boxes.size(); ++j)
      alike += j != i && ratio(boxes[i].w(), boxes[j].w()) <= kRiderSimilar && ratio(boxes[i].h(), boxes[j].h()) <= kRiderSimilar;
    out[i] = alike >= kMinSymmetricRiders - 1;
  }
  return out;
}

bool riders_stack(const RigBox& a, const RigBox& b) {
  const double ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
  return ox >= 0.5 * std::min(a.w(), b.w()) && a.y0 <= b.y1 && b.y0 <= a.y1;
}

std::vector<RigBox> rider_stacks(const std::vector<RigBox>& riders) {
  const size_t n = riders.size();
  std::vector<size_t> root(n);
  std::iota(root.begin(), root.end(), size_t{0});
  auto find = [&](size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      if (riders_stack(riders[i], riders[j])) root[find(i)] = find(j);
  std::vector<RigBox> box(n), out(n);
  for (size_t i = 0; i < n; ++i) box[find(i)].add(riders[i]);
  for (size_t i = 0; i < n; ++i) out[i] = box[find(i)];
  return out;
}

int rider_symmetry(const std::vector<RigBox>& stacks, const RigBox& wheel) {
  std::vector<double> angles;
  const Vec2 c = wheel.centre();
  for (size_t i = 0; i < stacks.size(); ++i) {
    bool seen = false;  // one angle per stack (every rider of it carries its box)
    for (size_t j = 0; j < i; ++j)
      seen = seen || (stacks[j].x0 == stacks[i].x0 && stacks[j].y0 == stacks[i].y0 && stacks[j].x1 == stacks[i].x1 &&
                      stacks[j].y1 == stacks[i].y1);
    if (!seen) angles.push_back(std::atan2(stacks[i].y0 - c.y, stacks[i].centre().x - c.x));
  }
  const int n = static_cast<int>(angles.size());
  if (n < kMinSymmetricRiders) return 0;
  std::sort(angles.begin(), angles.end());
  const double spacing = 2 * M_PI / n;
  for (int i = 0; i < n; ++i) {
    const double gap = i + 1 < n ? angles[i + 1] - angles[i] : angles[0] + 2 * M_PI - angles[i];
    if (std::fabs(gap - spacing) > 0.5 * spacing) return 0;
  }
  return n;
}

}  // namespace svgm
