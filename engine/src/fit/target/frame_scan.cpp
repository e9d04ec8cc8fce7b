// The target's held frames and shake, read before sampling (see frame_scan.h).
#include "fit/target/frame_scan.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "svgmotion/target_video.h"

namespace svgm {

namespace {

// Frames are scanned at this width (or the source's own, if narrower): shake of a pixel at the
// fitting width is a quarter pixel here, which phase correlation resolves to a few hundredths.
constexpr int kScanWidth = 128;
// Held frames are compared at this width, as the target's own retiming compares them.
constexpr int kHeldWidth = 64;

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const size_t m = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(m), v.end());
  return v[m];
}

}  // namespace

std::vector<int> held_runs(const std::vector<cv::Mat>& thumbs, double max_diff) {
  std::vector<int> start(thumbs.size(), 0);
  std::vector<cv::Mat> small(thumbs.size());
  for (size_t i = 0; i < thumbs.size(); ++i) {
    const int w = std::min(kHeldWidth, thumbs[i].cols);
    const int h = std::max(1, static_cast<int>(std::lround(double(thumbs[i].rows) * w / thumbs[i].cols)));
    cv::resize(thumbs[i], small[i], cv::Size(w, h), 0, 0, cv::INTER_AREA);
  }
  // Against the run's first frame, not the one before: a slow drift of a level or two per
  // frame is a motion, not a hold.
  for (size_t i = 1; i < thumbs.size(); ++i) {
    const cv::Mat& first = small[static_cast<size_t>(start[i - 1])];
    double lo = 0, hi = 0;
    if (first.size() == small[i].size()) cv::minMaxLoc(cv::abs(small[i] - first), &lo, &hi);
    start[i] = first.size() == small[i].size() && hi <= max_diff ? start[i - 1] : static_cast<int>(i);
  }
  return start;
}

void find_cadence(const std::vector<int>& run_start, FrameScan& scan) {
  const int N = static_cast<int>(run_start.size());
  std::vector<std::pair<int, int>> runs;  // (first frame, length)
  for (int i = 0; i < N; ++i)
    if (run_start[static_cast<size_t>(i)] == i) runs.push_back({i, 1});
    else ++runs.back().second;
  std::map<int, int> count;  // of each length, among the runs before the last
  for (size_t r = 0; r + 1 < runs.size(); ++r) ++count[runs[r].second];
  int mode = 1, n = 0;
  for (const auto& [len, c] : count)
    if (c > n) mode = len, n = c;
  const int before_last = static_cast<int>(runs.size()) - 1;
  scan.cadence = mode >= 2 && before_last >= 3 && n >= kCadenceMinShare * before_last ? mode : 1;
  scan.poses.clear();
  // A run of k whole cadences is k poses that look alike (a pose held twice as long); a run
  // between whole cadences (3:2 pulldown's runs of 3 at a cadence of 2) is one pose, its extra
  // frames repeats: a pose at first + 2 would be a repeat shown late.
  for (const auto& [first, len] : runs)
    for (int j = 0; j < std::max(1, len / scan.cadence); ++j) scan.poses.push_back(first + j * scan.cadence);
  if (N > 0 && scan.poses.back() != N - 1) scan.poses.push_back(N - 1);
}

std::vector<std::array<double, 2>> frame_path(const std::vector<cv::Mat>& frames, std::vector<double>* rigid_residual) {
  std::vector<std::array<double, 2>> path;
  if (frames.empty()) return path;
  path.push_back({0, 0});
  cv::Mat window;
  cv::createHanningWindow(window, frames[0].size(), CV_32F);
  cv::Mat prev = 255 - frames[0];  // ink as signal: the white paper correlates with nothing
  for (size_t i = 1; i < frames.size(); ++i) {
    cv::Mat cur = 255 - frames[i];
    const cv::Point2d d = cv::phaseCorrelate(prev, cur, window);
    path.push_back({path.back()[0] + d.x, path.back()[1] + d.y});
    if (rigid_residual) {
      cv::Mat moved;
      const cv::Matx23d m(1, 0, d.x, 0, 1, d.y);
      cv::warpAffine(prev, moved, m, prev.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
      const double before = cv::norm(cur, prev, cv::NORM_L1), after = cv::norm(cur, moved, cv::NORM_L1);
      rigid_residual->push_back(before > 0 ? after / before : 1);
    }
    prev = cur;
  }
  return path;
}

void judge_shake(const std::vector<std::array<double, 2>>& path, const std::vector<double>& rigid_residual, FrameScan& scan) {
  std::vector<double> off, step;
  for (size_t i = 1; i + 1 < path.size(); ++i)
    off.push_back(std::hypot(path[i][0] - 0.5 * (path[i - 1][0] + path[i + 1][0]),
                             path[i][1] - 0.5 * (path[i - 1][1] + path[i + 1][1])));
  for (size_t i = 1; i < path.size(); ++i) step.push_back(std::hypot(path[i][0] - path[i - 1][0], path[i][1] - path[i - 1][1]));
  scan.jitter_fit_px = median(off);
  scan.step_fit_px = median(step);
  scan.rigid_residual = rigid_residual.empty() ? 1 : median(rigid_residual);
  // Medians: a hop or a sudden turn moves one or two points of the path, shake all of them.
  scan.shaking = off.size() >= 3 && scan.jitter_fit_px >= kShakeMinFitPx &&
                 scan.jitter_fit_px >= kShakeMinStepShare * scan.step_fit_px && scan.rigid_residual <= kShakeMaxRigidResidual;
}

FrameScan scan_frames(const std::filesystem::path& source, int fit_width) {
  const TargetInfo info = probe_target(source);
  FrameScan scan;
  scan.frames = info.frames;
  const int w = std::max(1, std::min(kScanWidth, info.width));
  const int h = std::max(1, static_cast<int>(std::lround(double(info.height) * w / std::max(1, info.width))));
  // One pass over the clip, a grey thumbnail per frame (the thumbnails are what stays: 64 KB a
  // frame at 128 px).
  std::vector<cv::Mat> grey;
  grey.reserve(static_cast<size_t>(info.frames));
  const size_t px = static_cast<size_t>(w) * h;
  for_each_target_frame(source, w, h, [&](int, const float* f) {
    cv::Mat g(h, w, CV_32F);
    for (size_t p = 0; p < px; ++p)
      g.at<float>(static_cast<int>(p)) = 255.0f * (0.299f * f[4 * p] + 0.587f * f[4 * p + 1] + 0.114f * f[4 * p + 2]);
    grey.push_back(std::move(g));
  });
  scan.run_start = held_runs(grey);
  for (int i = 0; i < scan.frames; ++i)
    if (scan.run_start[static_cast<size_t>(i)] == i) scan.distinct.push_back(i);
  find_cadence(scan.run_start, scan);
  // The path over the distinct poses: a hold's repeats would read as a path that stops and
  // jumps, which is not shake.
  std::vector<cv::Mat> poses;
  for (int i : scan.distinct) poses.push_back(grey[static_cast<size_t>(i)]);
  std::vector<double> rigid;
  std::vector<std::array<double, 2>> path = frame_path(poses, &rigid);
  for (auto& p : path)
    for (double& v : p) v *= double(fit_width) / w;
  judge_shake(path, rigid, scan);
  return scan;
}

std::vector<int> spread_over_poses(const std::vector<int>& poses, int keyframes) {
  const int D = static_cast<int>(poses.size());
  if (keyframes >= D) return poses;
  std::vector<int> out;
  for (int k = 0; k < keyframes; ++k) {
    // round(k (D-1) / (K-1)) in integers, as load_target spreads keyframes over a clip.
    const int64_t num = 2 * int64_t{k} * (D - 1) + (keyframes - 1);
    out.push_back(poses[static_cast<size_t>(keyframes == 1 ? 0 : num / (2 * int64_t{keyframes - 1}))]);
  }
  return out;
}

}  // namespace svgm
