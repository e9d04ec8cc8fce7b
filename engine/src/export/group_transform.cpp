// Group motion as SVG transforms (see group_transform.h).
#include "export/group_transform.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fit/optimise/inbetween.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

constexpr int kMotionParams = 12;  // MOTION_PARAMS in kernels/motion.cl
constexpr int kParts = 6;          // numbers of a TransformParts
constexpr double kRadToDeg = 180.0 / M_PI;
// A scale below this (canvas units per unit) is a collapsed group: no inverse for the residual.
constexpr double kMinScale = 1e-6;
// Points per side of the grid an affine map is fitted through (group_affine): 5 x 5 sees the
// curvature a homography has between the corners.
constexpr int kGrid = 5;

void to_numbers(const TransformParts& p, double* out) {
  out[0] = p.tx, out[1] = p.ty, out[2] = p.rotate_deg, out[3] = p.skew_x_deg, out[4] = p.sx, out[5] = p.sy;
}
TransformParts from_numbers(const double* v) { return {v[0], v[1], v[2], v[3], v[4], v[5]}; }

}  // namespace

TransformParts decompose_affine(const Affine& m) {
  // [a c; b d] = R(θ) [sx  sy·tanκ; 0  sy]: the first column is R(θ) (sx, 0), the second
  // rotated back by -θ is (sy·tanκ, sy).
  TransformParts p;
  p.tx = m.e;
  p.ty = m.f;
  p.sx = std::hypot(m.a, m.b);
  const double th = std::atan2(m.b, m.a), cs = std::cos(th), sn = std::sin(th);
  p.rotate_deg = th * kRadToDeg;
  p.sy = -sn * m.c + cs * m.d;
  const double shear = cs * m.c + sn * m.d;  // sy · tan κ
  p.skew_x_deg = p.sy != 0 ? std::atan(shear / p.sy) * kRadToDeg : 0;
  return p;
}

Affine compose_affine(const TransformParts& p) {
  return Affine::translate(p.tx, p.ty) * Affine::rotate_deg(p.rotate_deg) * Affine::skew_x_deg(p.skew_x_deg) *
         Affine::scale(p.sx, p.sy);
}

double unwrap_degrees(double deg, double previous) { return deg + 360.0 * std::round((previous - deg) / 360.0); }

GroupAffine group_affine(const MotionParams& th, Vec2 origin, double scale, const Affine& view, double x0,
                         double y0, double x1, double y1) {
  // The least-squares affine map through the homography's images of a grid over the box. Not
  // the homography with its bottom row dropped: the motion model's w = 1 + p.f grows with the
  // distance from the canvas centre, so a small perspective far from the centre is mostly a
  // translation and scale the affine map should carry, not a deviation.
  std::vector<Vec2> from, to;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const Vec2 x{x0 + (x1 - x0) * i / (kGrid - 1), y0 + (y1 - y0) * j / (kGrid - 1)};
      from.push_back(x);
      to.push_back(apply_motion(th, x, origin, scale));
    }
  // Normal equations in coordinates relative to the box centre (well conditioned), one 3 x 3
  // system shared by both output coordinates: [u v 1] (a, c, e) = x', [u v 1] (b, d, f) = y'.
  const Vec2 mid{0.5 * (x0 + x1), 0.5 * (y0 + y1)};
  double m[3][3] = {}, rx[3] = {}, ry[3] = {};
  for (size_t k = 0; k < from.size(); ++k) {
    const double r[3] = {from[k].x - mid.x, from[k].y - mid.y, 1};
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) m[a][b] += r[a] * r[b];
      rx[a] += r[a] * to[k].x;
      ry[a] += r[a] * to[k].y;
    }
  }
  // The grid is symmetric about its centre, so the system is diagonal apart from the (u, v)
  // block: m[0][2] = m[1][2] = 0 (and m[0][1] = 0 too, but solve the block generally).
  const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  GroupAffine g;
  if (!(std::fabs(det) > 0) || !(m[2][2] > 0)) {  // a box of no area: translation only
    const Vec2 d = apply_motion(th, mid, origin, scale) - mid;
    g.canvas = view.inverse() * Affine::translate(d.x, d.y) * view;
    return g;
  }
  auto solve = [&](const double* rhs, double* out) {
    out[0] = (rhs[0] * m[1][1] - m[0][1] * rhs[1]) / det;
    out[1] = (m[0][0] * rhs[1] - m[1][0] * rhs[0]) / det;
    out[2] = rhs[2] / m[2][2];
  };
  double px[3], py[3];
  solve(rx, px);
  solve(ry, py);
  const Affine pixels = Affine{px[0], py[0], px[1], py[1], px[2], py[2]} * Affine::translate(-mid.x, -mid.y);
  g.canvas = view.inverse() * pixels * view;
  for (size_t k = 0; k < from.size(); ++k) {
    const Vec2 d = to[k] - pixels.apply(from[k]);
    const double dist = std::hypot(d.x, d.y);
    g.projective_px = std::max(g.projective_px, std::isfinite(dist) ? dist : std::numeric_limits<double>::infinity());
  }
  return g;
}

GroupMotionExport group_motion_export(const FitPlan& fplan, const RasterPlan& plan, const std::vector<float>& params,
                                      int keyframes, const Affine& view, int width, int height,
                                      const std::vector<double>& key_times, const std::vector<double>& frame_times,
                                      int max_inbetweens, bool closed, const std::vector<double>& written_times) {
  const int K = keyframes, G = fplan.n_groups;
  if (params.size() != static_cast<size_t>(K) * G * kMotionParams || key_times.size() != static_cast<size_t>(K))
    throw Error("internal: group motion does not match the fit");
  const Vec2 origin{0.5 * width, 0.5 * height};
  const double scale = 0.5 * width;

  // Per group: is it affine at every keyframe, and its decomposed canvas map per keyframe.
  std::vector<char> ok(static_cast<size_t>(G), 1);
  std::vector<double> parts(static_cast<size_t>(K) * G * kParts);
  GroupMotionExport out;
  for (int g = 0; g < G; ++g) {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (int e = fplan.group_first[g]; e < fplan.group_first[g + 1]; ++e) {
      const size_t i = static_cast<size_t>(fplan.group_cps[e]);
      x0 = std::min<double>(x0, plan.rest_cp[2 * i]), x1 = std::max<double>(x1, plan.rest_cp[2 * i]);
      y0 = std::min<double>(y0, plan.rest_cp[2 * i + 1]), y1 = std::max<double>(y1, plan.rest_cp[2 * i + 1]);
    }
    const std::string& id = fplan.group_ids[static_cast<size_t>(g)];
    double previous = 0;
    for (int k = 0; k < K && ok[g]; ++k) {
      MotionParams th{};
      const float* src = &params[(static_cast<size_t>(k) * G + g) * kMotionParams];
      std::copy(src, src + kMotionParams, th.begin());
      const GroupAffine ga = group_affine(th, origin, scale, view, x0, y0, x1, y1);
      TransformParts p = decompose_affine(ga.canvas);
      if (!(ga.projective_px <= kAffineTolerancePx)) {
        char buf[160];
        std::snprintf(buf, sizeof buf, ": not affine at keyframe %d (perspective moves its box by %.2f px), kept baked",
                      k, ga.projective_px);
        out.baked.push_back(id + buf);
        ok[g] = 0;
      } else if (!(p.sx > kMinScale && std::fabs(p.sy) > kMinScale)) {
        out.baked.push_back(id + ": collapsed at keyframe " + std::to_string(k) + ", kept baked");
        ok[g] = 0;
      }
      if (k > 0) p.rotate_deg = unwrap_degrees(p.rotate_deg, previous);
      previous = p.rotate_deg;
      to_numbers(p, &parts[(static_cast<size_t>(k) * G + g) * kParts]);
    }
    out.transform_groups += ok[g];
  }

  // The parameters splined at the written times, exactly as the points were.
  const InBetween written = in_between(parts, key_times, static_cast<size_t>(G) * kParts, frame_times,
                                       max_inbetweens, closed);
  if (written.times.size() != written_times.size())
    throw Error("internal: group motion written at other times than the shapes");
  const size_t P = plan.path_cp_first.size();
  out.paths.values = static_cast<int>(written.times.size());
  out.paths.as_transform.assign(P, 0);
  out.paths.motion.assign(written.times.size() * P, Affine{});
  for (size_t f = 0; f < P; ++f) {
    if (plan.path_cp_count[f] == 0) continue;
    const int g = fplan.cp_group[static_cast<size_t>(plan.path_cp_first[f])];
    if (g < 0 || !ok[static_cast<size_t>(g)]) continue;
    out.paths.as_transform[f] = 1;
    for (size_t v = 0; v < written.times.size(); ++v)
      out.paths.motion[v * P + f] =
          compose_affine(from_numbers(&written.points[(v * G + static_cast<size_t>(g)) * kParts]));
  }
  return out;
}

}  // namespace svgm
