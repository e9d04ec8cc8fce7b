// The CPU reference of kernels/loss.cl: the Gaussian-blurred MSE in double precision.
#pragma once

#include <array>
#include <vector>

namespace svgm::ref {

// One frame's blurred squared residual sum, Σ_{pixel, channel} E², with
// E = G_r ∗ X − G_t ∗ (T − bg), X = C − bg, C the premultiplied RGBA `image` composited over
// `background` bg, T the RGB of `target` (width * height * 4 values each), G_r and G_t the
// loss's Gaussians of σ `render_sigma` and 1 (raster/loss_taps.h), zero padding: the paper is
// blurred as the target is (at σ 1 this is G ∗ C − G ∗ T); above σ 1 both blurs pad by
// reflect-101 instead (raster/loss_taps.h, loss_reflects), as the kernels do. The loss of K frames is weight / (K·H·W·3) times the sum of their
// frame sums. With `chroma_sigma` > 0 and not `render_sigma`, G_r ∗ C is the per-group blur
// of chroma blur matching, A⁻¹ · diag(G_r, G_c, G_c) · A · C in YCbCr (raster/loss_taps.h).
// With `chroma_weight` w < 1 each pixel's E² is Eᵀ M E, M = w·I + (1 − w)·y yᵀ/|y|² (y the
// luma row): chroma alone counts w times (kernels/loss.cl's loss_metric).
double blurred_sq_sum(const std::vector<double>& image, const std::vector<float>& target,
                      int width, int height, const std::array<double, 4>& background,
                      double render_sigma = 1.0, double chroma_sigma = 0, double chroma_weight = 1);

}  // namespace svgm::ref
