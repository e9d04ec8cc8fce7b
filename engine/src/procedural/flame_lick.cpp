// A blaze's tongues licking up (see flame_lick.h).
#include "procedural/flame_lick.h"

#include <algorithm>
#include <cmath>

#include "procedural/motion_plan_internal.h"

namespace svgm {

using namespace motion_plan_internal;

double tongue_spacing(const std::vector<Vec2>& pts) {
  if (pts.empty()) return 0;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (Vec2 q : pts) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  const double W = x1 - x0, H = y1 - y0;
  if (!(W > 0) || !(H > 0)) return 0;
  // The top edge: per column its highest point (the least y); columns with none are left out.
  std::vector<Vec2> top(kTongueColumns, Vec2{0, 1e300});
  for (Vec2 q : pts) {
    const size_t c = static_cast<size_t>(std::clamp(static_cast<int>((q.x - x0) / W * kTongueColumns), 0, kTongueColumns - 1));
    if (q.y < top[c].y) top[c] = q;
  }
  std::vector<double> xs, ys;
  for (Vec2 q : top)
    if (q.y < 1e300) xs.push_back(q.x), ys.push_back(q.y);
  // Tips: the highest column between two notches at least kTongueProminence of the height lower
  // (the ends of the edge count as notches: a tongue at the side ends there). Walking the edge,
  // a tip is confirmed once the edge has fallen that far below it.
  const double drop = kTongueProminence * H;
  std::vector<double> tips;
  double best_y = 1e300, best_x = 0, low = -1e300;  // the candidate tip, the lowest point since the last tip
  bool rising = true;                                // the edge rose enough since the last tip
  for (size_t i = 0; i < xs.size(); ++i) {
    const double y = ys[i];
    if (rising) {
      if (y < best_y) best_y = y, best_x = xs[i];
      if (y > best_y + drop) {
        tips.push_back(best_x);
        rising = false;
        low = y;
      }
    } else {
      low = std::max(low, y);
      if (y < low - drop) rising = true, best_y = y, best_x = xs[i];
    }
  }
  if (rising && best_y < 1e300) tips.push_back(best_x);
  if (tips.size() < 2) return 0;
  return (tips.back() - tips.front()) / static_cast<double>(tips.size() - 1);
}

double tongue_phase(double spacing, double tip, double x) {
  if (!(spacing > 0)) return 0;
  const double g = (x - tip) / spacing, k = std::floor(g);
  const double s = std::clamp((g - k - 0.25) / 0.5, 0.0, 1.0);
  return 0.5 * (k + s * s * (3 - 2 * s));
}

Vec2 flame_lick(const ArmLobe& lobe, const PlannedAction& a, double amp, double t, Vec2 q) {
  double top = lobe.pivot.y;
  for (Vec2 o : lobe.outline) top = std::min(top, o.y);
  const double H = lobe.pivot.y - top;
  if (!(H > 0) || q.y >= lobe.pivot.y) return q;
  const double lean = std::tan(std::min(std::fabs(amp), 80.0) * M_PI / 180);
  const double B = std::min(0.5 * lean, kLickMax), A = 0.5 * lean * (amp < 0 ? -1 : 1);
  // The lick: up and down along the column by its tongue's phase; zero at the loop's ends (t = 0
  // and 1).
  const double phase = tongue_phase(lobe.tongue_spacing, lobe.tip.x, q.x), u = a.cycles * t;
  const double P = std::sin(kTau * (u - phase)) - std::sin(kTau * -phase);
  const double v = std::min((lobe.pivot.y - q.y) / H, 1.0);
  const double y = q.y - B * H * v * v * P;
  // The sway: every row by the square of its height after the lick (a translation of the row).
  const double w = std::max((lobe.pivot.y - y) / H, 0.0);
  return {q.x + A * H * w * w * oscillation(a, u), y};
}

}  // namespace svgm
