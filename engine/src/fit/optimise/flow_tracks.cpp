// Keyframe-to-keyframe optical flow for warm starts (see flow_tracks.h).
#include "fit/optimise/flow_tracks.h"
#include "svgmotion/atomic_file.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>


#include "svgmotion/error.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

void FlowField::sample(double x, double y, int w, int h, double* ox, double* oy, double* weight) const {
  *ox = *oy = *weight = 0;
  if (grid < 1 || dx.empty()) return;
  // Cell centres at (i + 0.5) / grid of the frame.
  const double gx = std::clamp(x / w * grid - 0.5, 0.0, grid - 1.0);
  const double gy = std::clamp(y / h * grid - 0.5, 0.0, grid - 1.0);
  const int x0 = std::min(static_cast<int>(gx), grid - 1), y0 = std::min(static_cast<int>(gy), grid - 1);
  const int x1 = std::min(x0 + 1, grid - 1), y1 = std::min(y0 + 1, grid - 1);
  const double fx = gx - x0, fy = gy - y0;
  auto lerp = [&](const std::vector<float>& v) {
    return (1 - fy) * ((1 - fx) * v[y0 * grid + x0] + fx * v[y0 * grid + x1]) +
           fy * ((1 - fx) * v[y1 * grid + x0] + fx * v[y1 * grid + x1]);
  };
  *ox = lerp(dx) * w / width;
  *oy = lerp(dy) * h / height;
  *weight = lerp(certainty);
}

std::vector<FlowField> compute_flows(const TargetFrames& t, int grid) {
  std::vector<FlowField> out(t.keyframes);
  const int W = t.width, H = t.height;
  auto grey = [&](int k) {
    cv::Mat g(H, W, CV_8UC1);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const float* c = &t.rgba[((static_cast<size_t>(k) * H + y) * W + x) * 4];
        g.at<uchar>(y, x) = cv::saturate_cast<uchar>(255.f * (0.299f * c[0] + 0.587f * c[1] + 0.114f * c[2]));
      }
    return g;
  };
  cv::Mat prev = grey(0);
  for (int k = 1; k < t.keyframes; ++k) {
    cv::Mat next = grey(k), fwd, bwd;
    // Farnebäck with a 5-level pyramid reaches large motions; window 21 suits flat drawings.
    cv::calcOpticalFlowFarneback(prev, next, fwd, 0.5, 5, 21, 3, 7, 1.5, 0);
    cv::calcOpticalFlowFarneback(next, prev, bwd, 0.5, 5, 21, 3, 7, 1.5, 0);
    FlowField f;
    f.grid = grid;
    f.width = W;
    f.height = H;
    for (int gy = 0; gy < grid; ++gy)
      for (int gx = 0; gx < grid; ++gx) {
        const int x = std::min(W - 1, static_cast<int>((gx + 0.5) * W / grid));
        const int y = std::min(H - 1, static_cast<int>((gy + 0.5) * H / grid));
        const cv::Point2f d = fwd.at<cv::Point2f>(y, x);
        // Forward-backward check: follow the flow, come back, measure the miss.
        const int xb = std::clamp(static_cast<int>(std::lround(x + d.x)), 0, W - 1);
        const int yb = std::clamp(static_cast<int>(std::lround(y + d.y)), 0, H - 1);
        const cv::Point2f b = bwd.at<cv::Point2f>(yb, xb);
        const double miss = std::hypot(d.x + b.x, d.y + b.y);
        f.dx.push_back(d.x);
        f.dy.push_back(d.y);
        f.certainty.push_back(static_cast<float>(std::exp(-miss * miss / 2.0)));
      }
    out[k] = std::move(f);
    prev = next;
  }
  return out;
}

void write_tracks(const std::filesystem::path& file, const std::vector<FlowField>& flows) {
  nlohmann::json j = {{"kind", "keyframe flow"}, {"flows", nlohmann::json::array()}};
  for (const FlowField& f : flows)
    j["flows"].push_back({{"grid", f.grid}, {"width", f.width}, {"height", f.height}, {"dx", f.dx},
                          {"dy", f.dy}, {"certainty", f.certainty}});
  write_file_atomic(file, json_text(j) + "\n");
}

std::vector<FlowField> read_tracks(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error(file.string() + ": cannot open");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) throw Error(file.string() + ": not valid JSON");
  std::vector<FlowField> out;
  if (!j.contains("flows")) return out;  // e.g. the `none` tracker's {"tracks": []}
  try {
    for (const auto& f : j.at("flows")) {
      FlowField x;
      x.grid = f.at("grid");
      x.width = f.at("width");
      x.height = f.at("height");
      x.dx = f.at("dx").get<std::vector<float>>();
      x.dy = f.at("dy").get<std::vector<float>>();
      x.certainty = f.at("certainty").get<std::vector<float>>();
      const size_t n = static_cast<size_t>(x.grid) * x.grid;
      if (x.grid > 0 && (x.dx.size() != n || x.dy.size() != n || x.certainty.size() != n))
        throw Error(file.string() + ": flow arrays do not match the grid");
      out.push_back(std::move(x));
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error(file.string() + ": malformed tracks: " + e.what());
  }
  return out;
}

}  // namespace svgm
