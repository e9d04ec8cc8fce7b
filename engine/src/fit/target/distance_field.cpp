// Distance fields from masks (distance_field.h).
#include "fit/target/distance_field.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "svgmotion/error.h"

namespace svgm {

void distance_field_from_mask(const uint8_t* mask, int width, int height, float* sdf) {
  const size_t px = static_cast<size_t>(width) * height;
  if (std::none_of(mask, mask + px, [](uint8_t m) { return m != 0; })) {
    std::fill(sdf, sdf + px, static_cast<float>(width + height));
    return;
  }
  // Background = 255 (non-zero) so that distanceTransform measures the distance to the nearest
  // mask pixel; the precise mask makes it the exact Euclidean distance between pixel centres.
  cv::Mat background(height, width, CV_8U);
  for (int y = 0; y < height; ++y) {
    uint8_t* b = background.ptr<uint8_t>(y);
    const uint8_t* m = mask + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) b[x] = m[x] ? 0 : 255;
  }
  cv::Mat dist;
  cv::distanceTransform(background, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  for (int y = 0; y < height; ++y) {
    const float* d = dist.ptr<float>(y);
    const uint8_t* m = mask + static_cast<size_t>(y) * width;
    float* s = sdf + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) s[x] = m[x] ? 0.0f : d[x];
  }
}

void fill_distance_fields(TargetFrames& t) {
  const size_t px = static_cast<size_t>(t.width) * t.height;
  if (t.mask.size() != px * static_cast<size_t>(t.keyframes)) throw Error("internal: a distance field without its mask");
  std::vector<float>(px * static_cast<size_t>(t.keyframes)).swap(t.sdf);
  for (int k = 0; k < t.keyframes; ++k)
    distance_field_from_mask(&t.mask[static_cast<size_t>(k) * px], t.width, t.height, &t.sdf[static_cast<size_t>(k) * px]);
}

}  // namespace svgm
