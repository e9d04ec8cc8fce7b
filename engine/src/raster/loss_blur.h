// The loss's render blur as the raster program takes it: which build of the program, and the
// data its kernels read (kernels/prelude.cl, LossBlur).
//
// The paper's blur (σ 1 for render and target, zero padding, every channel alike) is compiled
// into the program as constants, its loops written out: the program of every fit whose video
// is not softer than the render, and of every plain render. Any other blur (blur matching's
// render σ, chroma σ and chroma weight, fit/target/blur_match.h) runs on the LOSS_MATCHED
// build, one program for every σ, whose taps, radius, padding and chroma weight are a kernel
// argument: blur matching picks σ in steps of 0.05 from the video, and with the taps compiled
// in each σ was a program of its own, compiled by the first run that chose it.
#pragma once

#include <cstdint>
#include <string>

#include "raster/loss_taps.h"

namespace svgm {

// LossBlur of kernels/prelude.cl, byte for byte: tap j of the luma and of the chroma groups
// (luma, chroma, chroma, 0), j = 0..kMaxLossRadius (0 beyond the radius), the radius, reflect
// padding, the per-group blur in YCbCr, the chroma weight.
struct alignas(16) LossBlurArgs {
  float g[kMaxLossRadius + 1][4] = {};
  int32_t radius = 0;
  int32_t reflect = 0;
  int32_t ycc = 0;
  float chroma_weight = 1;
};
static_assert(sizeof(LossBlurArgs) == (kMaxLossRadius + 1) * 16 + 16, "LossBlur's layout (kernels/prelude.cl)");

// Whether the blur is the paper's, compiled into the program (no LOSS_MATCHED).
inline bool loss_blur_is_paper(double sigma, double chroma_sigma, double chroma_weight) {
  return sigma == kLossSigma && chroma_sigma == sigma && chroma_weight == 1;
}

// The raster program's build option for that blur: "" (the paper's) or " -DLOSS_MATCHED".
inline std::string loss_blur_options(double sigma, double chroma_sigma, double chroma_weight) {
  return loss_blur_is_paper(sigma, chroma_sigma, chroma_weight) ? "" : " -DLOSS_MATCHED";
}

// The kernels' LossBlur for a render σ, chroma σ (= σ: every channel alike) and chroma weight:
// loss_taps of each (raster/loss_taps.h) in float, the larger radius, reflect padding above
// σ 1 (loss_reflects), YCbCr when the chroma σ is its own.
LossBlurArgs loss_blur_args(double sigma, double chroma_sigma, double chroma_weight);

}  // namespace svgm
