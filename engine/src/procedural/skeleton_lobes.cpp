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

// A piece drawn apart from the silhouette (a mask component other than the one the skeleton
// reads) held at a limb's far half: the pixel pair, piece and figure, nearest each other.
struct Hold {
  int component = -1, limb = -1;
  cv::Point piece, figure;
};

// The pieces held by the limbs: each component other than the figure's whose nearest figure
// pixel, at most `gap` px away, belongs to a limb and lies beyond the middle of its base-tip
// chord (a hand, a paw: not the shoulder, where a separate head or collar sits).
std::vector<Hold> held_pieces(const motion::Skeleton& sk, const motion::Figure& fig, const cv::Mat& regions, int gap) {
  std::vector<Hold> best(sk.component_area.size());
  std::vector<int> best_d2(sk.component_area.size(), gap * gap + 1);
  for (int y = 0; y < sk.height; ++y)
    for (int x = 0; x < sk.width; ++x) {
      const int c = sk.labels.at<int>(y, x);
      if (c < 0 || c == fig.component) continue;
      for (int v = std::max(0, y - gap); v <= std::min(sk.height - 1, y + gap); ++v)
        for (int u = std::max(0, x - gap); u <= std::min(sk.width - 1, x + gap); ++u) {
          const int d2 = (u - x) * (u - x) + (v - y) * (v - y);
          if (d2 >= best_d2[c] || sk.labels.at<int>(v, u) != fig.component) continue;
          best_d2[c] = d2;
          best[c] = {c, regions.at<int>(v, u), {x, y}, {u, v}};
        }
    }
  std::vector<Hold> out;
  for (const Hold& h : best) {
    if (h.component < 0 || h.limb < 0 || h.limb >= static_cast<int>(fig.limbs.size())) continue;
    const motion::Limb& l = fig.limbs[h.limb];
    const Vec2 f{static_cast<double>(h.figure.x), static_cast<double>(h.figure.y)};
    if (std::hypot(f.x - l.base.x, f.y - l.base.y) >= 0.5 * std::hypot(l.tip_pos.x - l.base.x, l.tip_pos.y - l.base.y))
      out.push_back(h);
  }
  return out;
}

// The limb the skeleton labelled the head when the figure's head is drawn apart from it (an
// openmoji person's head is a disc above the shoulders, a gap of white between): then the one
// limb rising from the upper body is a raised arm, not the head (a polo player's throwing arm
// was the head, and "throws the ball" found no arm). The head apart: a piece of the mask other
// than the figure's, held by no limb, above the core's middle, nearer the core's middle than
// the labelled head's tip and nearer its axis across. -1 when the head limb is the head.
int head_drawn_apart(const motion::Skeleton& sk, const motion::Figure& fig, const std::vector<Hold>& holds) {
  int head = -1;
  for (size_t i = 0; i < fig.limbs.size(); ++i)
    if (fig.limbs[i].kind == motion::LimbKind::Head) head = static_cast<int>(i);
  if (head < 0) return -1;
  const size_t n = sk.component_area.size();
  std::vector<double> sx(n, 0), sy(n, 0), count(n, 0);
  for (int y = 0; y < sk.height; ++y)
    for (int x = 0; x < sk.width; ++x)
      if (const int c = sk.labels.at<int>(y, x); c >= 0 && c != fig.component) sx[c] += x, sy[c] += y, count[c] += 1;
  const motion::Limb& L = fig.limbs[static_cast<size_t>(head)];
  const Vec2 core = fig.core_centre;
  const double reach = std::hypot(L.tip_pos.x - core.x, L.tip_pos.y - core.y), across = std::fabs(L.tip_pos.x - core.x);
  for (size_t c = 0; c < n; ++c) {
    if (count[c] < kHeadApartMin * sk.component_area[static_cast<size_t>(fig.component)]) continue;
    if (std::any_of(holds.begin(), holds.end(), [&](const Hold& h) { return h.component == static_cast<int>(c); })) continue;
    const Vec2 m{sx[c] / count[c], sy[c] / count[c]};
    if (m.y < core.y && std::hypot(m.x - core.x, m.y - core.y) < reach && std::fabs(m.x - core.x) < across) return head;
  }
  return -1;
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
  const std::vector<Hold> holds = held_pieces(sk, fig, regions, std::max(1, static_cast<int>(std::lround(kHeldGap * kSkeletonSize))));
  const int arm_not_head = head_drawn_apart(sk, fig, holds);
  std::vector<ArmLobe> out;
  for (size_t li = 0; li < fig.limbs.size(); ++li) {
    const motion::Limb& l = fig.limbs[li];
    if (l.relative_length < kLimbMinLength || l.base_index >= l.path.size()) continue;
    // The silhouette the limb owns (its tip included, which the thinning leaves short of the
    // outline), grown by a pixel so its own outline's curves lie inside, as its outline.
    cv::Mat own = regions == static_cast<int>(li);
    // What the limb holds moves with it, joined to it across the gap so the lobe is one outline.
    for (const Hold& h : holds)
      if (h.limb == static_cast<int>(li)) {
        own |= sk.labels == h.component;
        cv::line(own, h.piece, h.figure, cv::Scalar(255), 3);
      }
    cv::dilate(own, own, cv::Mat(), cv::Point(-1, -1), 1);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(own, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    size_t biggest = 0;
    for (size_t c = 1; c < contours.size(); ++c)
      if (cv::contourArea(contours[c]) > cv::contourArea(contours[biggest])) biggest = c;
    if (contours.empty() || contours[biggest].size() < 3) continue;
    ArmLobe lobe;
    lobe.kind = static_cast<int>(li) == arm_not_head ? LobeKind::Arm : lobe_kind(l.kind);
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
