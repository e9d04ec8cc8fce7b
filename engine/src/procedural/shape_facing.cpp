// A figure's facing from its outline (see shape_facing.h).
#include "procedural/shape_facing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace svgm {

SideProfile side_profile(const Rig& rig) {
  SideProfile out;
  const RigBox& F = rig.figure;
  if (F.empty() || F.w() <= 0 || F.h() <= 0) return out;
  std::vector<double> top(kProfileBins, 1e300), bot(kProfileBins, -1e300);
  auto put = [&](Vec2 p) {
    const int i = std::clamp(static_cast<int>((p.x - F.x0) / F.w() * kProfileBins), 0, kProfileBins - 1);
    top[i] = std::min(top[i], p.y), bot[i] = std::max(bot[i], p.y);
  };
  // Each element's points and the lines between them, a column's width apart at most: a long
  // straight edge (a lorry's roof) has points only at its ends.
  const double step = F.w() / kProfileBins;
  for (const RigElement& e : rig.elements)
    for (size_t k = 0; k < e.points.size(); ++k) {
      const Vec2 a = e.points[k], b = e.points[k + 1 < e.points.size() ? k + 1 : 0];
      const int n = std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / step)));
      for (int j = 0; j < n; ++j) put({a.x + (b.x - a.x) * j / n, a.y + (b.y - a.y) * j / n});
    }
  const int end = std::max(1, static_cast<int>(std::lround(kEndShare * kProfileBins)));
  auto read = [&](int from, int to) {
    EndProfile p;
    double t = 0, th = 0;
    int n = 0;
    for (int i = from; i < to; ++i)
      if (bot[i] >= top[i]) t += (top[i] - F.y0) / F.h(), th += (bot[i] - top[i]) / F.h(), ++n;
    if (n > 0) p.top = t / n, p.thick = th / n;
    return p;
  };
  out.left = read(0, end);
  out.right = read(kProfileBins - end, kProfileBins);
  out.empty = false;
  return out;
}

int shape_facing(const Rig& rig, FigureClass figure, std::string* why) {
  if (figure != FigureClass::Wheeled) return 0;
  const SideProfile p = side_profile(rig);
  // > 0: the right end's top is lower than the left end's (y down): the front is on the right.
  const double drop = p.right.top - p.left.top;
  if (p.empty || std::fabs(drop) < kVehicleStep) return 0;
  const int side = drop > 0 ? 1 : -1;
  if (why) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "its shape: the %s end low (its top at %.2f of its height), the other tall and square (%.2f)",
                  side < 0 ? "left" : "right", side < 0 ? p.left.top : p.right.top, side < 0 ? p.right.top : p.left.top);
    *why = buf;
  }
  return side;
}

}  // namespace svgm
