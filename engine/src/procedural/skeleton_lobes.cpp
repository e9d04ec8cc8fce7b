// Limbs from the silhouette's skeleton (see skeleton_lobes.h).
#include "procedural/skeleton_lobes.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "motion/limbs.h"
#include "motion/skeleton.h"
#include "geometry/curve_samples.h"

namespace svgm {

namespace {

LobeKind lobe_kind(motion::LimbKind k) {
  switch (k) {
    case motion::LimbKind::Arm: return LobeKind::Arm;
    case motion::LimbKind::Leg: return LobeKind::Leg;
    case motion::LimbKind::Head: return LobeKind::Head;
    case motion::LimbKind::Tail: return LobeKind::Tail;
    case motion::LimbKind::Other: break;
  }
  return LobeKind::Other;
}

}  // namespace

std::vector<ArmLobe> skeleton_lobes(const Scene& scene, const std::vector<int>& paths) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  std::vector<std::vector<std::vector<Vec2>>> rings(paths.size());
  std::vector<std::vector<char>> closed(paths.size());  // per ring: its subpath is closed
  for (size_t k = 0; k < paths.size(); ++k) {
    const Path& p = scene.paths[static_cast<size_t>(paths[k])];
    const bool fill = p.has_fill && p.fill.a > 0, stroke = p.has_stroke && p.stroke.color.a > 0 && p.stroke.width > 0;
    if (p.opacity <= 0 || !(fill || stroke)) continue;
    for (const Subpath& sp : p.subpaths) {
      std::vector<Vec2> ring;
      append_curve_samples(sp, 8, true, ring);
      for (const Vec2& q : ring) x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
      if (ring.size() >= 2) {
        rings[k].push_back(std::move(ring));
        closed[k].push_back(sp.closed);
      }
    }
  }
  if (!(x1 > x0 && y1 > y0)) return {};
  const double s = kSkeletonSize / std::max(x1 - x0, y1 - y0), pad = 3;
  const int W = static_cast<int>(std::ceil((x1 - x0) * s + 2 * pad)), H = static_cast<int>(std::ceil((y1 - y0) * s + 2 * pad));
  auto px = [&](Vec2 q) { return cv::Point(static_cast<int>(std::lround((q.x - x0) * s + pad)), static_cast<int>(std::lround((q.y - y0) * s + pad))); };
  auto canvas = [&](Vec2 m) { return Vec2{(m.x - pad) / s + x0, (m.y - pad) / s + y0}; };
  cv::Mat mask(H, W, CV_8U, cv::Scalar(0));
  for (size_t k = 0; k < paths.size(); ++k) {
    if (rings[k].empty()) continue;
    const Path& p = scene.paths[static_cast<size_t>(paths[k])];
    std::vector<std::vector<cv::Point>> poly;
    for (const auto& ring : rings[k]) {
      poly.emplace_back();
      for (const Vec2& q : ring) poly.back().push_back(px(q));
    }
    if (p.has_fill && p.fill.a > 0) {
      cv::Mat one(H, W, CV_8U, cv::Scalar(0));
      cv::fillPoly(one, poly, cv::Scalar(255));  // rings of one path together: holes stay holes
      mask |= one;
    }
    if (p.has_stroke && p.stroke.color.a > 0 && p.stroke.width > 0)
      for (size_t r = 0; r < poly.size(); ++r)
        cv::polylines(mask, std::vector<std::vector<cv::Point>>{poly[r]}, closed[k][r] != 0,
                      cv::Scalar(255), std::max(1, static_cast<int>(std::lround(p.stroke.width * s))));
  }
  const motion::Skeleton sk = motion::skeletonise(mask);
  const motion::Figure fig = motion::find_limbs(sk);
  const cv::Mat regions = motion::limb_regions(sk, fig);
  std::vector<ArmLobe> out;
  for (size_t li = 0; li < fig.limbs.size(); ++li) {
    const motion::Limb& l = fig.limbs[li];
    if (l.relative_length < kLimbMinLength || l.base_index >= l.path.size()) continue;
    // The silhouette the limb owns (its tip included, which the thinning leaves short of the
    // outline), grown by a pixel so its own outline's curves lie inside, as its outline.
    cv::Mat own = regions == static_cast<int>(li);
    cv::dilate(own, own, cv::Mat(), cv::Point(-1, -1), 1);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(own, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    size_t biggest = 0;
    for (size_t c = 1; c < contours.size(); ++c)
      if (cv::contourArea(contours[c]) > cv::contourArea(contours[biggest])) biggest = c;
    if (contours.empty() || contours[biggest].size() < 3) continue;
    ArmLobe lobe;
    lobe.kind = lobe_kind(l.kind);
    lobe.side = l.side;
    const double r = std::max(l.radius[l.base_index], 1.0);
    const Vec2 n{-l.direction.y * r, l.direction.x * r};
    lobe.pivot = canvas(l.base);
    lobe.base0 = canvas(l.base - n);
    lobe.base1 = canvas(l.base + n);
    lobe.tip = canvas(l.tip_pos);
    for (const cv::Point& c : contours[biggest]) lobe.outline.push_back(canvas(Vec2{static_cast<double>(c.x), static_cast<double>(c.y)}));
    out.push_back(std::move(lobe));
  }
  return out;
}

}  // namespace svgm
