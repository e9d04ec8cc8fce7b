// The kernels' LossBlur from the loss's σ (see loss_blur.h).
#include "raster/loss_blur.h"

#include <algorithm>
#include <vector>

namespace svgm {

LossBlurArgs loss_blur_args(double sigma, double chroma_sigma, double chroma_weight) {
  LossBlurArgs a;
  const std::vector<double> g = loss_taps(sigma);
  // With a chroma σ of its own, chroma takes its own taps in YCbCr; else the luma taps in
  // every channel, in RGB (the same blur without the change of coordinates).
  a.ycc = chroma_sigma != sigma;
  const std::vector<double> gc = a.ycc ? loss_taps(chroma_sigma) : g;
  a.radius = static_cast<int32_t>(std::max(g.size(), gc.size())) - 1;
  for (size_t j = 0; j < g.size(); ++j) a.g[j][0] = static_cast<float>(g[j]);
  for (size_t j = 0; j < gc.size(); ++j) a.g[j][1] = a.g[j][2] = static_cast<float>(gc[j]);
  a.reflect = loss_reflects(sigma);
  a.chroma_weight = static_cast<float>(chroma_weight);
  return a;
}

}  // namespace svgm
