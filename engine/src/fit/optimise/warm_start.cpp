// Point tracking and similarity fitting for keyframe warm starts (see warm_start.h).
#include "fit/optimise/warm_start.h"

#include <opencv2/video/tracking.hpp>

#include <algorithm>
#include <cmath>

namespace svgm {

std::vector<double> window_isotropy(const std::vector<uint8_t>& image, int width, int height,
                                   const std::vector<Vec2>& at, int r) {
  std::vector<double> iso(at.size(), 0.0);
  auto pixel = [&](int x, int y) { return static_cast<double>(image[static_cast<size_t>(y) * width + x]); };
  for (size_t i = 0; i < at.size(); ++i) {
    if (!std::isfinite(at[i].x) || !std::isfinite(at[i].y)) continue;
    // Clamped before the cast: a point far off the image has no window there.
    const int px = static_cast<int>(std::clamp(std::floor(at[i].x), -1e6, 1e6));
    const int py = static_cast<int>(std::clamp(std::floor(at[i].y), -1e6, 1e6));
    double xx = 0, xy = 0, yy = 0;
    for (int y = std::max(1, py - r); y <= std::min(height - 2, py + r); ++y)
      for (int x = std::max(1, px - r); x <= std::min(width - 2, px + r); ++x) {
        const double gx = 0.5 * (pixel(x + 1, y) - pixel(x - 1, y));
        const double gy = 0.5 * (pixel(x, y + 1) - pixel(x, y - 1));
        xx += gx * gx, xy += gx * gy, yy += gy * gy;
      }
    const double mean = 0.5 * (xx + yy), dev = std::sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy);
    if (mean > 0) iso[i] = (mean - dev) / (mean + dev);
  }
  return iso;
}

PointTracks track_points(const std::vector<uint8_t>& prev, const std::vector<uint8_t>& next,
                         int width, int height, const std::vector<Vec2>& from) {
  PointTracks out;
  out.to = from;
  out.weight.assign(from.size(), 0.0);
  if (from.empty()) return out;
  const cv::Mat a(height, width, CV_8UC1, const_cast<uint8_t*>(prev.data()));
  const cv::Mat b(height, width, CV_8UC1, const_cast<uint8_t*>(next.data()));
  std::vector<cv::Point2f> p0, p1, back;
  for (const Vec2& v : from) p0.emplace_back(static_cast<float>(v.x - 0.5), static_cast<float>(v.y - 0.5));
  std::vector<uchar> st1, st2;
  std::vector<float> err;
  const cv::Size win(15, 15);  // the usual LK window; 3 pyramid levels reach ~60 px motions
  const cv::TermCriteria term(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01);
  cv::calcOpticalFlowPyrLK(a, b, p0, p1, st1, err, win, 3, term);
  cv::calcOpticalFlowPyrLK(b, a, p1, back, st2, err, win, 3, term);
  out.isotropy = window_isotropy(prev, width, height, from, win.width / 2);
  for (size_t i = 0; i < from.size(); ++i) {
    if (!st1[i] || !st2[i]) continue;
    const double fb = std::hypot(back[i].x - p0[i].x, back[i].y - p0[i].y);
    out.to[i] = {p1[i].x + 0.5, p1[i].y + 0.5};
    out.weight[i] = fb < 1.0 ? std::exp(-fb * fb / 0.25) : 0.0;  // ~1 below a quarter pixel
  }
  return out;
}

std::optional<Similarity> fit_similarity(const std::vector<Vec2>& from, const std::vector<Vec2>& to,
                                         const std::vector<double>& weight) {
  double W = 0;
  Vec2 mf, mt;
  int used = 0;
  for (size_t i = 0; i < from.size(); ++i) {
    if (weight[i] <= 0) continue;
    W += weight[i];
    mf = mf + weight[i] * from[i];
    mt = mt + weight[i] * to[i];
    ++used;
  }
  if (used < 3 || W <= 1e-9) return std::nullopt;
  mf = (1.0 / W) * mf;
  mt = (1.0 / W) * mt;
  // Umeyama in 2-D with complex numbers: a = Σ w (t − mt) conj(f − mf) / Σ w |f − mf|².
  double re = 0, im = 0, var = 0;
  for (size_t i = 0; i < from.size(); ++i) {
    if (weight[i] <= 0) continue;
    const Vec2 f = from[i] - mf, t = to[i] - mt;
    re += weight[i] * (t.x * f.x + t.y * f.y);
    im += weight[i] * (t.y * f.x - t.x * f.y);
    var += weight[i] * (f.x * f.x + f.y * f.y);
  }
  if (var <= 1e-9) return std::nullopt;
  Similarity s;
  s.scale = std::hypot(re, im) / var;
  s.angle = std::atan2(im, re);
  if (!(s.scale > 0.5 && s.scale < 2.0)) return std::nullopt;  // a track that broke, not motion
  const double c = std::cos(s.angle), sn = std::sin(s.angle);
  s.shift = mt - s.scale * Vec2{c * mf.x - sn * mf.y, sn * mf.x + c * mf.y};
  return s;
}

void compose_similarity(MotionParams& th, const Similarity& s, Vec2 origin, double scale) {
  // In normalised units the similarity is n ↦ ς R n + t_s with t_s = (ς R o + b − o) / s.
  // With H(n) = R_θ Sh S (n − c) + c + t: ς R_φ H(n) = R_{θ+φ} Sh (ς S)(n − c) + c + t' with
  // t' = ς R_φ (c + t) + t_s − c.
  const double c = std::cos(s.angle), sn = std::sin(s.angle);
  auto rot = [&](Vec2 v) { return Vec2{c * v.x - sn * v.y, sn * v.x + c * v.y}; };
  const Vec2 ts = (1.0 / scale) * (s.scale * rot(origin) + s.shift - origin);
  const Vec2 cc{th[9], th[10]}, t{th[0], th[1]};
  const Vec2 t2 = s.scale * rot(cc + t) + ts - cc;
  th[0] = t2.x;
  th[1] = t2.y;
  th[2] += s.angle;
  th[3] *= s.scale;
  th[4] *= s.scale;
}

bool compose_affine(MotionParams& th, const Affine& m, Vec2 origin, double scale) {
  if (th[7] != 0 || th[8] != 0) return false;
  // The group's linear part L = R(rot) [[1, shx], [shy, 1]] diag(sx, sy) and its new one A L.
  const double cr = std::cos(th[2]), sr = std::sin(th[2]);
  const double b00 = th[3], b01 = th[5] * th[4], b10 = th[6] * th[3], b11 = th[4];  // Sh S
  const double l00 = cr * b00 - sr * b10, l01 = cr * b01 - sr * b11, l10 = sr * b00 + cr * b10, l11 = sr * b01 + cr * b11;
  const double n00 = m.a * l00 + m.c * l10, n01 = m.a * l01 + m.c * l11, n10 = m.b * l00 + m.d * l10, n11 = m.b * l01 + m.d * l11;
  const double det = n00 * n11 - n01 * n10;
  if (!(std::fabs(det) > 1e-12)) return false;
  // QR: the first column fixes the turn and sx; R^T (A L) is then [[sx, shx sy], [0, sy]]. A
  // mirrored map (a figure turned round to go, its back shown: det < 0) takes a negative sx
  // (motion.cl's S is signed), sy staying positive; refused, a zebra turned round had no known
  // start and its fit stayed facing its own way.
  const double flip = det < 0 ? -1 : 1;
  const double sx = flip * std::hypot(n00, n10), rot = std::atan2(flip * n10, flip * n00);
  const double c2 = std::cos(rot), s2 = std::sin(rot);
  const double u = c2 * n01 + s2 * n11, sy = -s2 * n01 + c2 * n11;
  // Translation: f = A L (n - c) + A (c + t) + t_a, in normalised units t_a = (A o + b - o) / s.
  const Vec2 cc{th[9], th[10]}, t{th[0], th[1]};
  const Vec2 ao = m.apply(origin);
  const Vec2 ta = (1.0 / scale) * (ao - origin);
  const Vec2 ct{cc.x + t.x, cc.y + t.y};
  const Vec2 act{m.a * ct.x + m.c * ct.y, m.b * ct.x + m.d * ct.y};
  th[0] = act.x + ta.x - cc.x;
  th[1] = act.y + ta.y - cc.y;
  th[2] = rot;
  th[3] = sx;
  th[4] = sy;
  th[5] = u / sy;
  th[6] = 0;
  return true;
}

}  // namespace svgm
