// The host motion model (see motion_model.h and the essay in kernels/motion.cl).
#include "fit/optimise/motion_model.h"

#include <cmath>

namespace svgm {

MotionParams identity_params(double cx, double cy) {
  MotionParams p{};
  p[3] = p[4] = 1;
  p[9] = cx;
  p[10] = cy;
  return p;
}

Vec2 apply_motion(const MotionParams& th, Vec2 x, Vec2 origin, double scale) {
  const Vec2 n = (1.0 / scale) * (x - origin);
  const Vec2 c{th[9], th[10]};
  const Vec2 a = n - c;
  const Vec2 b{th[3] * a.x, th[4] * a.y};
  const Vec2 d{b.x + th[5] * b.y, th[6] * b.x + b.y};
  const double cs = std::cos(th[2]), sn = std::sin(th[2]);
  const Vec2 f = Vec2{cs * d.x - sn * d.y, sn * d.x + cs * d.y} + c + Vec2{th[0], th[1]};
  const double w = th[7] * f.x + th[8] * f.y + 1.0;
  return origin + scale * ((1.0 / w) * f);
}

}  // namespace svgm
