// Round parts of a mask (wheel_circles.h): circular holes, round components, bottom arcs.
#include "motion/wheel_circles.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace svgm::motion {

namespace {

constexpr double kRound = 0.8;         // 4 pi area / perimeter^2 of a polygonised circle: ~0.9
constexpr double kArcFit = 0.06;       // RMS residual of a bottom arc, share of its radius (+0.6 px)
constexpr double kArcSpan = 0.55;      // a bottom arc's half-width as a share of its radius
constexpr double kArcDepth = 0.2;      // how far it bulges below its sides, share of its radius
constexpr double kArcFilled = 0.9;     // share of its disc inside the mask

// Share of the disc (centre c, 0.9 r) inside the mask: a wheel's arc bounds a filled disc; a
// rounded paw's arc fitted to a bigger circle than the leg is wide does not.
double disc_filled(const cv::Mat& mask, Vec2 c, double r) {
  int in = 0, all = 0;
  const double rr = 0.9 * r;
  for (int y = static_cast<int>(c.y - rr); y <= static_cast<int>(c.y + rr); ++y)
    for (int x = static_cast<int>(c.x - rr); x <= static_cast<int>(c.x + rr); ++x) {
      if ((x - c.x) * (x - c.x) + (y - c.y) * (y - c.y) > rr * rr) continue;
      ++all;
      in += x >= 0 && y >= 0 && x < mask.cols && y < mask.rows && mask.at<uchar>(y, x);
    }
  return all ? static_cast<double>(in) / all : 0;
}

double circularity(const std::vector<cv::Point>& c) {
  const double a = cv::contourArea(c), p = cv::arcLength(c, true);
  return p > 0 ? 4 * M_PI * a / (p * p) : 0;
}

// Kasa's algebraic circle fit: x^2 + y^2 + D x + E y + F = 0 in least squares.
bool fit_circle(const std::vector<cv::Point2d>& pts, Vec2& c, double& r, double& rms) {
  if (pts.size() < 5) return false;
  cv::Mat A(static_cast<int>(pts.size()), 3, CV_64F), b(static_cast<int>(pts.size()), 1, CV_64F), x;
  for (size_t i = 0; i < pts.size(); ++i) {
    A.at<double>(static_cast<int>(i), 0) = pts[i].x;
    A.at<double>(static_cast<int>(i), 1) = pts[i].y;
    A.at<double>(static_cast<int>(i), 2) = 1;
    b.at<double>(static_cast<int>(i)) = -(pts[i].x * pts[i].x + pts[i].y * pts[i].y);
  }
  if (!cv::solve(A, b, x, cv::DECOMP_SVD)) return false;
  c = {-x.at<double>(0) / 2, -x.at<double>(1) / 2};
  const double r2 = c.x * c.x + c.y * c.y - x.at<double>(2);
  if (!(r2 > 0)) return false;
  r = std::sqrt(r2);
  double se = 0;
  for (const auto& p : pts) {
    const double d = std::hypot(p.x - c.x, p.y - c.y) - r;
    se += d * d;
  }
  rms = std::sqrt(se / static_cast<double>(pts.size()));
  return true;
}

// Bulges of the bottom outline: from each local lowest run of the profile, out on both sides
// while the outline keeps rising (a step of at most `max_step` px; a circle's bottom is flat for
// a while, but past its first few pixels of rise no more than two flat steps in a row), then a
// circle through those columns.
void bottom_arcs(const cv::Mat& mask, double min_radius, std::vector<Circle>& out) {
  std::vector<int> bottom(mask.cols, -1);
  for (int x = 0; x < mask.cols; ++x)
    for (int y = mask.rows - 1; y >= 0; --y)
      if (mask.at<uchar>(y, x)) {
        bottom[x] = y;
        break;
      }
  const int max_step = std::max(3, mask.cols / 40);
  auto grow = [&](int from, int dir) {
    int x = from, flat = 0;
    while (true) {
      const int nx = x + dir;
      if (nx < 0 || nx >= mask.cols || bottom[nx] < 0) break;
      const int rise = bottom[x] - bottom[nx];
      if (rise < 0 || rise > max_step) break;
      flat = rise == 0 ? flat + 1 : 0;
      if (flat > 2 && bottom[from] - bottom[nx] >= 4) break;  // flat again once well up the arc
      x = nx;
    }
    return x;
  };
  for (int x = 1; x + 1 < mask.cols; ++x) {
    if (bottom[x] < 0 || bottom[x - 1] > bottom[x]) continue;  // start of a lowest run only
    if (bottom[x - 1] == bottom[x]) continue;
    int run_end = x;
    while (run_end + 1 < mask.cols && bottom[run_end + 1] == bottom[x]) ++run_end;
    if (run_end + 1 < mask.cols && bottom[run_end + 1] > bottom[x]) continue;  // not a local lowest
    const int l = grow(x, -1), r = grow(run_end, 1);
    std::vector<cv::Point2d> pts;
    for (int k = l; k <= r; ++k) pts.emplace_back(k, bottom[k] + 0.5);
    Vec2 c;
    double rad = 0, rms = 0;
    if (!fit_circle(pts, c, rad, rms) || rad < min_radius) continue;
    const double depth = bottom[x] - std::max(bottom[l], bottom[r]);
    const bool ok = rms <= kArcFit * rad + 0.6 && 0.5 * (r - l) >= kArcSpan * rad && depth >= kArcDepth * rad &&
                    c.y < bottom[x] && c.x >= l && c.x <= r && disc_filled(mask, c, rad) >= kArcFilled;
    if (ok) out.push_back({c, rad, "bottom arc"});
    x = run_end;
  }
}

}  // namespace

std::vector<Circle> find_circles(const cv::Mat& mask_in, double min_radius) {
  std::vector<Circle> out;
  if (mask_in.empty() || mask_in.type() != CV_8U) return out;
  if (min_radius <= 0) min_radius = std::max(mask_in.cols, mask_in.rows) / 40.0;
  cv::Mat mask = mask_in != 0;
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> tree;
  cv::findContours(mask.clone(), contours, tree, cv::RETR_CCOMP, cv::CHAIN_APPROX_NONE);
  for (size_t i = 0; i < contours.size(); ++i) {
    const bool hole = tree[i][3] >= 0;
    cv::Point2f c;
    float r = 0;
    cv::minEnclosingCircle(contours[i], c, r);
    if (r < min_radius || circularity(contours[i]) < kRound) continue;
    if (hole) {
      out.push_back({{c.x, c.y}, r, "hole"});
      continue;
    }
    // A round component: a disc, or a ring whose hole is round and concentric.
    const double filled = cv::contourArea(contours[i]) / (M_PI * r * r);
    if (filled > 0.8) out.push_back({{c.x, c.y}, r, "component"});
  }
  bottom_arcs(mask, min_radius, out);
  // One circle per wheel: a ring is both a round hole and a round component, and its lower arc.
  std::vector<Circle> unique;
  for (const auto& c : out) {
    bool seen = false;
    for (const auto& u : unique)
      seen |= std::hypot(c.centre.x - u.centre.x, c.centre.y - u.centre.y) < 0.5 * std::max(c.radius, u.radius);
    if (!seen) unique.push_back(c);
  }
  return unique;
}

}  // namespace svgm::motion
