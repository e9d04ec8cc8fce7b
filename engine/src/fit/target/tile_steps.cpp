// The camera's steps as a fixed blend of tile steps: see tile_steps.h for the method and why.
#include "fit/target/tile_steps.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace svgm {

namespace {

// Tiles are an eighth of the frame's width (at least 16 px), overlapping by half.
constexpr int kTileShare = 8;
constexpr int kMinTile = 16;
// A tile has texture when its normal matrix's smaller eigenvalue is at least this per pixel
// (mean squared ink gradient across its weaker direction; a blurred ink edge peaks near 0.1
// per pixel, so this asks for a little of an edge running each way).
constexpr double kMinTexture = 2.5e-7;
// A tile's fit that ends this far (px) from the whole frame's step slid off (a part moved into
// or out of it): the tile is left out.
constexpr double kMaxFromStart = 4;
constexpr int kMaxIterations = 20;
// The blend's weights must pin both directions: smaller over larger eigenvalue at least this.
constexpr double kMinConditioning = 1e-3;

// The tile's translation d from `a` to `b` (b(x + d) = a(x) over the tile), started at `start`:
// inverse-compositional Gauss-Newton, so the gradient and normal matrix are the template's.
// Nothing when the tile lacks texture or the fit slides off.
std::optional<cv::Vec2d> tile_step(const cv::Mat& a, const cv::Mat& b, const cv::Mat& gx, const cv::Mat& gy,
                                   const cv::Rect& r, const cv::Vec2d& start, cv::Matx22d* normal) {
  const cv::Mat ta = a(r), tx = gx(r), ty = gy(r);
  const double h00 = tx.dot(tx), h01 = tx.dot(ty), h11 = ty.dot(ty);
  const double mid = 0.5 * (h00 + h11), half = std::sqrt(0.25 * (h00 - h11) * (h00 - h11) + h01 * h01);
  if (!(mid - half >= kMinTexture * r.area())) return std::nullopt;
  *normal = cv::Matx22d(h00, h01, h01, h11);
  const double det = h00 * h11 - h01 * h01;
  cv::Mat warped;
  cv::Vec2d d = start;
  for (int it = 0; it < kMaxIterations; ++it) {
    // b sampled at the tile's pixels moved by d (an inverse map: no per-pixel map to build).
    const cv::Matx23d at(1, 0, r.x + d[0], 0, 1, r.y + d[1]);
    cv::warpAffine(b, warped, at, r.size(), cv::INTER_CUBIC | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
    const cv::Mat res = warped - ta;
    const double b0 = tx.dot(res), b1 = ty.dot(res);
    const double dx = (h11 * b0 - h01 * b1) / det, dy = (h00 * b1 - h01 * b0) / det;
    if (!std::isfinite(dx) || !std::isfinite(dy)) return std::nullopt;
    d -= cv::Vec2d(dx, dy);
    if (std::max(std::fabs(dx), std::fabs(dy)) < 1e-4) break;
  }
  if (!(cv::norm(d - start) <= kMaxFromStart)) return std::nullopt;
  return d;
}

}  // namespace

TileStepBlend::TileStepBlend(cv::Size size) : size_(size) {
  const int side = std::max(kMinTile, size.width / kTileShare), stride = std::max(1, side / 2);
  for (int y = 0; y + side <= size.height; y += stride)
    for (int x = 0; x + side <= size.width; x += stride) tiles_.push_back(TileStepBlend::Tile{cv::Rect(x, y, side, side), true, cv::Matx22d::zeros(), {}});
}

TileStepBlend::~TileStepBlend() = default;

void TileStepBlend::add(const cv::Mat& a, const cv::Mat& b, const std::optional<std::array<double, 2>>& start) {
  registered_.push_back(start.has_value());
  if (!start || a.size() != size_ || b.size() != size_) {
    registered_.back() = false;
    return;
  }
  cv::Mat gx, gy;
  cv::Sobel(a, gx, CV_32F, 1, 0, 1, 0.5, 0, cv::BORDER_REPLICATE);
  cv::Sobel(a, gy, CV_32F, 0, 1, 1, 0.5, 0, cv::BORDER_REPLICATE);
  const cv::Vec2d from((*start)[0], (*start)[1]);
  for (Tile& tile : tiles_) {
    if (!tile.usable) continue;
    cv::Matx22d normal;
    const auto d = tile_step(a, b, gx, gy, tile.rect, from, &normal);
    if (!d) {
      tile.usable = false;
      tile.step.clear();
      continue;
    }
    tile.weight += normal;
    tile.step.push_back(*d);
  }
}

std::optional<std::vector<std::array<double, 2>>> TileStepBlend::steps() const {
  cv::Matx22d total = cv::Matx22d::zeros();
  for (const Tile& tile : tiles_)
    if (tile.usable) total += tile.weight;
  const double mid = 0.5 * (total(0, 0) + total(1, 1));
  const double half = std::sqrt(0.25 * (total(0, 0) - total(1, 1)) * (total(0, 0) - total(1, 1)) + total(0, 1) * total(0, 1));
  if (!(mid > 0) || !((mid - half) / (mid + half) >= kMinConditioning)) return std::nullopt;
  const cv::Matx22d inverse = total.inv();
  std::vector<std::array<double, 2>> out(registered_.size(), {0, 0});
  size_t k = 0;  // index among the registered steps
  for (size_t t = 0; t < registered_.size(); ++t) {
    if (!registered_[t]) continue;
    cv::Vec2d sum(0, 0);
    for (const Tile& tile : tiles_)
      if (tile.usable) sum += tile.weight * tile.step[k];
    const cv::Vec2d s = inverse * sum;
    out[t] = {s[0], s[1]};
    ++k;
  }
  return out;
}

}  // namespace svgm
