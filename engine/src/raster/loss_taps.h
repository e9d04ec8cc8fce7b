// The 1-D taps of the image loss's Gaussian blur, shared by the kernels' build options, the
// host's loss constants and the CPU reference.
//
// The loss compares G_r ∗ C with G_t ∗ T (kernels/loss.cl): the render blurred by G_r, the
// target by G_t, Gaussians truncated at a radius and normalised over their taps. The paper's
// loss is G_r = G_t with σ = 1 and radius 2 (5 taps). Blur matching (fit/target/blur_match.h) widens G_r alone when the video is
// softer than the render, so that a blurred video is matched by blurring the drawing rather
// than by shrinking its thin parts and rounding its corners: G_r = G_t ∗ G_v, G_v the video's
// own blur, and σ = sqrt(1 + σ_v²) names it.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace svgm {

// The loss's σ in pixels (paper, appendix).
constexpr double kLossSigma = 1.0;

// Above the paper's σ the render's blur is the target's own (the paper's 5 taps) composed with
// a Gaussian of the video's excess blur σ_v = sqrt(σ² − 1), sampled to 3σ_v (at most 6 taps
// a side): then G_r ∗ C = G_t ∗ (G_v ∗ C), the render blurred as a soft video is, and compared
// through the same blur as the target. A single Gaussian of σ cut at a radius of 4 is not
// G_t ∗ G_v: at σ 1.7 (a 512-px video blurred σ 1.5) its taps ended at 2.4σ, and blur matching
// chose σ 1.20 for that video at 256 px where the composition is 1.25 (bat, twemoji 1f987).
constexpr int kMaxVideoRadius = 6;
constexpr int kMaxLossRadius = 2 + kMaxVideoRadius;  // the kernels' LOSS_R_MAX

inline double video_sigma(double sigma) { return sigma > kLossSigma ? std::sqrt(sigma * sigma - kLossSigma * kLossSigma) : 0; }
inline int video_radius(double sigma) {
  return std::min(kMaxVideoRadius, static_cast<int>(std::ceil(3 * video_sigma(sigma) - 1e-9)));
}
inline int loss_radius(double sigma) { return 2 + (sigma > kLossSigma ? video_radius(sigma) : 0); }

// The normalised Gaussian of `sigma` over j = -R..R, as a full stencil.
inline std::vector<double> gaussian_stencil(double sigma, int R) {
  std::vector<double> g(static_cast<size_t>(2 * R + 1));
  double sum = 0;
  for (int j = -R; j <= R; ++j) sum += g[static_cast<size_t>(j + R)] = std::exp(-0.5 * j * j / (sigma * sigma));
  for (double& v : g) v /= sum;
  return g;
}

// g_0..g_R, R = loss_radius(σ): at σ <= 1 the Gaussian of σ normalised over 5 taps (the
// paper's at σ = 1); above, the paper's taps composed with the video's Gaussian (see above).
inline std::vector<double> loss_taps(double sigma) {
  const int R = loss_radius(sigma);
  std::vector<double> full = gaussian_stencil(std::min(sigma, kLossSigma), 2);
  if (sigma > kLossSigma) {
    const int rv = video_radius(sigma);
    const std::vector<double> v = gaussian_stencil(video_sigma(sigma), rv);
    std::vector<double> c(static_cast<size_t>(2 * R + 1), 0.0);
    for (int i = -2; i <= 2; ++i)
      for (int j = -rv; j <= rv; ++j) c[static_cast<size_t>(i + j + R)] += full[static_cast<size_t>(i + 2)] * v[static_cast<size_t>(j + rv)];
    full = c;
  }
  return std::vector<double>(full.begin() + R, full.end());
}

// The padding of the loss's blurs at the frame's border. The paper's loss pads with zeros, the
// render and the target alike. Once blur matching widens the render's blur (σ > 1) both blurs
// pad by reflection instead (reflect-101: index −1 reads 1, n reads n − 2): a soft video is
// blurred from a scene that goes on beyond the frame (a camera, a model; a filter pads by
// reflection), so its ink stays dark up to the border, and a render blurred over paper beyond
// the frame faded there: no pose fitted both, and the fitter fattened every part that ran off
// the frame (the blurred bat's wings: 25-45 % of its error at 1024 px lay within 12 px of the
// border at 512). With both blurs reflected the render's (G_t ∗ G_v) is exactly G_t applied to
// the render blurred as the video is (a reflect-101 blur of a symmetric stencil keeps the
// mirror symmetry), so the model is the video's own where the border mirrors the scene.
inline bool loss_reflects(double render_sigma) { return render_sigma > kLossSigma; }

// Reflect-101 of index k into [0, n): exact for k within n − 1 of the frame, clamped beyond
// (a frame narrower than a stencil), as the kernels' loss_reflect (prelude.cl).
inline int reflect101(int k, int n) {
  if (k < 0) k = -k;
  if (k >= n) k = 2 * (n - 1) - k;
  return std::clamp(k, 0, n - 1);
}

// The loss's blur on the host, in double: `stencil` (g_{-R}..g_R) applied separably to W x H
// pixels of 3 interleaved channels, with zero padding or, with `reflect`, reflect-101 padding;
// with `adjoint`, the transpose of that operator (the same as the blur with zero padding; with
// reflection the taps that read a mirrored pixel give back to it). Shared by the loss's
// constants (raster_cl_backward.cpp) and blur matching (fit/target/blur_match.cpp).
std::vector<double> blur_rgb(const std::vector<double>& in, int W, int H, const std::vector<double>& stencil,
                             bool reflect = false, bool adjoint = false);

// The taps as a full stencil, g_{-R}..g_R.
inline std::vector<double> loss_stencil(double sigma) {
  const std::vector<double> t = loss_taps(sigma);
  const int R = static_cast<int>(t.size()) - 1;
  std::vector<double> s(static_cast<size_t>(2 * R + 1));
  for (int j = -R; j <= R; ++j) s[static_cast<size_t>(j + R)] = t[static_cast<size_t>(std::abs(j))];
  return s;
}

// Chroma blur matching: the render's blur per channel group in YCbCr (BT.601 without
// offsets), B = A⁻¹ · diag(G_σ, G_σc, G_σc) · A. A⁻¹'s first column is (1, 1, 1) and its
// chroma columns span the colours of zero luma weight, so B is "luma blurred at σ, chroma at
// σc", and B = G_σ when σc = σ. Video codecs keep luma sharp and chroma soft (4:2:0
// subsampling, coarser chroma quantisation): matching that by a softer chroma blur keeps the
// fitter from moving edges between colours of similar luma to imitate it.
// kYcc: A (rows Y, Cb, Cr of R, G, B); kYccInv: A⁻¹ (rows R, G, B of Y, Cb, Cr).
constexpr double kYcc[3][3] = {{0.299, 0.587, 0.114},
                               {-0.299 / 1.772, -0.587 / 1.772, (1 - 0.114) / 1.772},
                               {(1 - 0.299) / 1.402, -0.587 / 1.402, -0.114 / 1.402}};
constexpr double kYccInv[3][3] = {{1, 0, 1.402},
                                  {1, -0.114 * 1.772 / 0.587, -0.299 * 1.402 / 0.587},
                                  {1, 1.772, 0}};

// B (or, with `adjoint`, Bᵀ = Aᵀ · diag(G_σ, G_σc, G_σc) · A⁻ᵀ) applied to W x H pixels of 3
// interleaved RGB channels, zero or (`reflect`) reflect-101 padding, in double. With σc = σ it
// is blur_rgb with loss_stencil(σ), the same arithmetic.
std::vector<double> render_blur(const std::vector<double>& in, int W, int H, double sigma, double chroma_sigma,
                                bool adjoint = false, bool reflect = false);

// M·e at every RGB triple of `e` (interleaved): M = w·I + (1 − w)·y yᵀ/|y|², y = kYcc's luma
// row. A residual of chroma alone (yᵀe = 0) counts w times, one of luma alone fully
// (kernels/loss.cl's loss_metric, in double).
std::vector<double> chroma_metric(const std::vector<double>& e, double w);

}  // namespace svgm
