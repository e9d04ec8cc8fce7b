// The video's blur at the frame's border, taken out of a target so the loss can match it.
//
// Blur matching (fit/target/blur_match.h) fits a soft video by blurring the render by the
// video's own blur G_v, with zero padding: beyond the frame the render is paper. A soft video
// is not blurred that way where the figure runs off the frame: a camera or a model blurs a
// scene that goes on beyond it, a filter pads by reflection, so the video's ink stays dark up
// to the border while the render's fades there. No pose fits both; the fitter fattened every
// part that crossed the border (the blurred bat's wings: 25-45 % of the error at 1024 px of
// its 13 moving keyframes sat within 12 px of the frame's border at 512).
//
// The correction: the ink the outside blurred into the frame, G_v,reflect ∗ D − G_v,zero ∗ D
// (D the target less the paper), estimated from the target itself mirrored at the border,
// taken out of D. Exact where the target is uniform across the border band, close where it is
// smooth there (the outside is blurred twice); pixels farther than G_v's radius from the
// border are not touched.
#pragma once

#include <vector>

namespace svgm {

// `d`: W x H pixels of 3 interleaved channels, the target less the paper. Returns the outside's
// share of the video's blur at each pixel, 0 (exactly) beyond the stencil's radius from the
// border and everywhere when `render_sigma` (the loss's, raster/loss_taps.h) is the paper's σ
// or less (no video blur): the caller subtracts it from the target, touching no other bits.
std::vector<double> outside_blur(const std::vector<double>& d, int W, int H, double render_sigma);

// d minus outside_blur(d, ...), in place.
void remove_outside_blur(std::vector<double>& d, int W, int H, double render_sigma);

}  // namespace svgm
