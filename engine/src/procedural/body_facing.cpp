// An animal's facing from its silhouette (see body_facing.h).
#include "procedural/body_facing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace svgm {

BodyEnds body_ends(const Rig& rig) {
  BodyEnds out;
  const RigBox& F = rig.figure;
  if (F.empty() || F.w() <= 0 || F.h() <= 0) return out;
  const double s = kBodyMaskSize / std::max(F.w(), F.h());
  const int W = std::max(4, static_cast<int>(std::lround(F.w() * s))), H = std::max(4, static_cast<int>(std::lround(F.h() * s)));
  auto px = [&](Vec2 q) {
    return cv::Point(std::clamp(static_cast<int>(std::floor((q.x - F.x0) * s)), 0, W - 1), std::clamp(static_cast<int>(std::floor((q.y - F.y0) * s)), 0, H - 1));
  };
  cv::Mat mask(H, W, CV_8U, cv::Scalar(0));
  const int line = std::max(1, static_cast<int>(std::lround(kLineWidth * kBodyMaskSize)));
  for (const RigElement& e : rig.elements) {
    if (e.points.size() < 2) continue;
    std::vector<cv::Point> poly;
    for (Vec2 q : e.points) poly.push_back(px(q));
    if (e.thin) cv::polylines(mask, std::vector<std::vector<cv::Point>>{poly}, false, cv::Scalar(255), line);
    else cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{poly}, cv::Scalar(255));
  }
  // The ground columns: those with silhouette in the bottom rows.
  int g0 = W, g1 = -1;
  const int ground = std::max(1, static_cast<int>(std::lround(kGroundShare * H)));
  for (int x = 0; x < W; ++x)
    for (int y = H - ground; y < H; ++y)
      if (mask.at<uchar>(y, x)) {
        g0 = std::min(g0, x), g1 = std::max(g1, x);
        break;
      }
  if (g1 < 0) return out;
  auto count = [&](int from, int to) {  // silhouette pixels in columns [from, to)
    int n = 0;
    for (int x = std::max(0, from); x < std::min(W, to); ++x) n += cv::countNonZero(mask.col(x));
    return n;
  };
  const double area = static_cast<double>(W) * H;
  out.overhang_left = count(0, g0) / area;
  out.overhang_right = count(g1 + 1, W) / area;
  const int end = std::max(1, static_cast<int>(std::lround(kBodyEndShare * W)));
  out.fill_left = count(0, end) / (static_cast<double>(end) * H);
  out.fill_right = count(W - end, W) / (static_cast<double>(end) * H);
  out.empty = false;
  return out;
}

int body_facing(const Rig& rig, FigureClass figure, std::string* why) {
  if (figure != FigureClass::Quadruped && figure != FigureClass::Bird) return 0;
  const BodyEnds e = body_ends(rig);
  if (e.empty) return 0;
  // > 0: the right end overhangs more, and ends slimmer, than the left.
  const double over = e.overhang_right - e.overhang_left, slim = e.fill_left - e.fill_right;
  const int side = over >= kBodyStep && slim >= kBodyStep ? 1 : over <= -kBodyStep && slim <= -kBodyStep ? -1 : 0;
  if (side != 0 && why) {
    char buf[240];
    std::snprintf(buf, sizeof buf, "its shape: the %s end held out beyond its feet (%.2f of its box, the other %.2f) and slimmer (%.2f filled, the other %.2f)",
                  side < 0 ? "left" : "right", side < 0 ? e.overhang_left : e.overhang_right, side < 0 ? e.overhang_right : e.overhang_left,
                  side < 0 ? e.fill_left : e.fill_right, side < 0 ? e.fill_right : e.fill_left);
    *why = buf;
  }
  return side;
}

}  // namespace svgm
