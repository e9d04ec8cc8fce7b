// Per-frame colour correction against the drawing's colours (see colour_correction.h).
#include "fit/target/colour_correction.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace svgm {

namespace {

// A pixel is flat when no 8-neighbour differs by more than this in any channel (8-bit: ~15
// levels). JPEG at quality 20 and H.264 keep flat regions well within it; edges exceed it.
constexpr float kFlatTolerance = 0.06f;
// A match: the nearest colour within this Euclidean RGB distance, and at most kRatio times the
// distance to the second nearest. 0.3 admits 15% shading of a mid-tone and an 8% tint; the
// ratio keeps two similar colours of the drawing from being confused.
constexpr float kMatchDistance = 0.3f;
constexpr float kRatio = 0.5f;
constexpr int kMinPixels = 16;      // a colour needs this many flat pixels to count
constexpr int kRounds = 4;          // match / fit alternations
constexpr double kRidge = 0.02;     // per unit of evidence weight, towards the identity map
constexpr float kMaxChange = 0.35f; // a map moving some colour further than this is not trusted
// Shading: a flat pixel's gain against a colour is the g in [kMinGain, kMaxGain] that brings
// g * colour nearest to it. Only colours at least kShadeLuma bright give evidence (a gain of a
// near-black is mostly noise; white is the paper, which is not shaded). The gains are smoothed
// over boxes of kShadeBox of the frame's larger side (three passes: nearly a Gaussian), and a
// pixel is corrected where the smoothed evidence covers at least kShadeSupport of its window.
constexpr float kMinGain = 0.7f, kMaxGain = 1.3f;
constexpr float kShadeLuma = 0.2f;
constexpr double kShadeBox = 1.0 / 12;
constexpr float kShadeSupport = 0.05f;

struct Match {
  int index = -1;
  float d1 = 0;
};

Match nearest(const float* c, const std::vector<std::array<float, 3>>& colours) {
  float d1 = 1e9f, d2 = 1e9f;
  int best = -1;
  for (size_t i = 0; i < colours.size(); ++i) {
    const float dr = c[0] - colours[i][0], dg = c[1] - colours[i][1], db = c[2] - colours[i][2];
    const float d = dr * dr + dg * dg + db * db;
    if (d < d1) {
      d2 = d1;
      d1 = d;
      best = static_cast<int>(i);
    } else if (d < d2) {
      d2 = d;
    }
  }
  d1 = std::sqrt(d1);
  d2 = std::sqrt(d2);
  if (best < 0 || d1 > kMatchDistance || d1 > kRatio * d2) return {};
  return {best, d1};
}

bool is_white(const std::array<float, 3>& p) { return p[0] == 1 && p[1] == 1 && p[2] == 1; }

// The gain g in [kMinGain, kMaxGain] that brings g * p nearest to c (1 for white: the paper is
// not shaded, and a grey is not a shaded white).
float best_gain(const float* c, const std::array<float, 3>& p) {
  const float pp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
  if (is_white(p) || pp <= 0) return 1;
  return std::clamp((c[0] * p[0] + c[1] * p[1] + c[2] * p[2]) / pp, kMinGain, kMaxGain);
}

// The nearest colour with a free gain per colour (shading darkens or lightens a colour, it does
// not change its hue): distance from c to g * colour at the best g, with the same acceptance
// as nearest(). Returns the gain in `gain`.
Match nearest_shaded(const float* c, const std::vector<std::array<float, 3>>& colours, float& gain) {
  float d1 = 1e9f, d2 = 1e9f, g1 = 1;
  int best = -1;
  for (size_t i = 0; i < colours.size(); ++i) {
    const auto& p = colours[i];
    const float g = best_gain(c, p);
    const float dr = c[0] - g * p[0], dg = c[1] - g * p[1], db = c[2] - g * p[2];
    const float d = dr * dr + dg * dg + db * db;
    if (d < d1) {
      d2 = d1;
      d1 = d;
      best = static_cast<int>(i);
      g1 = g;
    } else if (d < d2) {
      d2 = d;
    }
  }
  d1 = std::sqrt(d1);
  d2 = std::sqrt(d2);
  if (best < 0 || d1 > kMatchDistance || d1 > kRatio * d2) return {};
  gain = g1;
  return {best, d1};
}

// Three passes of a (2r+1)-wide box blur along rows then columns, in place (edges clamped).
void box_blur(std::vector<float>& v, int w, int h, int r) {
  std::vector<float> line;
  auto pass = [&](int n, int stride, int count, int step) {
    line.resize(static_cast<size_t>(n));
    for (int l = 0; l < count; ++l) {
      float* a = v.data() + static_cast<size_t>(l) * step;
      for (int rep = 0; rep < 3; ++rep) {
        for (int i = 0; i < n; ++i) line[static_cast<size_t>(i)] = a[static_cast<size_t>(i) * stride];
        double acc = 0;
        for (int i = -r; i <= r; ++i) acc += line[static_cast<size_t>(std::clamp(i, 0, n - 1))];
        for (int i = 0; i < n; ++i) {
          a[static_cast<size_t>(i) * stride] = static_cast<float>(acc / (2 * r + 1));
          acc += line[static_cast<size_t>(std::min(i + r + 1, n - 1))] - line[static_cast<size_t>(std::max(i - r, 0))];
        }
      }
    }
  };
  pass(w, 1, h, w);  // rows
  pass(h, w, w, 1);  // columns
}

// Which colour a flat pixel shows, and its gain against it: the plain nearest colour when one
// clearly explains it, else the nearest by hue (a shaded part can sit between two colours of
// the drawing, a darkened body pink beside its darker cheeks, and fail the ratio test).
Match classify(const float* c, const std::vector<std::array<float, 3>>& colours, float& gain) {
  Match m = nearest(c, colours);
  if (m.index >= 0) {
    gain = best_gain(c, colours[static_cast<size_t>(m.index)]);
    return m;
  }
  return nearest_shaded(c, colours, gain);
}

void apply(const std::array<float, 12>& m, const float* c, float* out) {
  for (int j = 0; j < 3; ++j)
    out[j] = std::clamp(m[4 * j] * c[0] + m[4 * j + 1] * c[1] + m[4 * j + 2] * c[2] + m[4 * j + 3], 0.f, 1.f);
}

}  // namespace

ColourCorrection correct_colours(float* rgba, int w, int h, const std::vector<std::array<float, 3>>& palette) {
  ColourCorrection out;
  std::vector<std::array<float, 3>> colours;
  for (const auto& c : palette)
    if (std::find(colours.begin(), colours.end(), c) == colours.end()) colours.push_back(c);
  if (std::find(colours.begin(), colours.end(), std::array<float, 3>{1, 1, 1}) == colours.end())
    colours.push_back({1, 1, 1});

  // Flat pixels, found once on the uncorrected frame (an affine map keeps flatness roughly).
  std::vector<int> flat;
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const float* p = rgba + (static_cast<size_t>(y) * w + x) * 4;
      bool ok = true;
      for (int dy = -1; dy <= 1 && ok; ++dy)
        for (int dx = -1; dx <= 1 && ok; ++dx) {
          const float* q = rgba + (static_cast<size_t>(y + dy) * w + x + dx) * 4;
          ok = std::fabs(q[0] - p[0]) <= kFlatTolerance && std::fabs(q[1] - p[1]) <= kFlatTolerance &&
               std::fabs(q[2] - p[2]) <= kFlatTolerance;
        }
      if (ok) flat.push_back(y * w + x);
    }

  std::array<float, 12> map = out.map;
  const size_t nc = colours.size();
  for (int round = 0; round < kRounds; ++round) {
    std::vector<int> count(nc, 0);
    std::vector<Match> match(flat.size());
    for (size_t i = 0; i < flat.size(); ++i) {
      float c[3];
      apply(map, rgba + static_cast<size_t>(flat[i]) * 4, c);
      // By hue too: without it a frame whose main colour is shaded had only white left, and
      // was not corrected at all (octopus, shading ramp: 9 of 15 keyframes).
      float gain = 1;
      match[i] = classify(c, colours, gain);
      if (match[i].index >= 0) ++count[static_cast<size_t>(match[i].index)];
    }
    // Normal equations, each colour weighing 1 in total: (XᵀWX + λI) m_j = XᵀW t_j + λ e_j.
    Eigen::Matrix4d xtx = Eigen::Matrix4d::Zero();
    Eigen::Matrix<double, 4, 3> xtt = Eigen::Matrix<double, 4, 3>::Zero();
    int used = 0;
    for (size_t i = 0; i < flat.size(); ++i) {
      const int ci = match[i].index;
      if (ci < 0 || count[static_cast<size_t>(ci)] < kMinPixels) continue;
      const float* c = rgba + static_cast<size_t>(flat[i]) * 4;
      const Eigen::Vector4d x(c[0], c[1], c[2], 1.0);
      const double wgt = 1.0 / count[static_cast<size_t>(ci)];
      xtx.noalias() += wgt * x * x.transpose();
      for (int j = 0; j < 3; ++j) xtt.col(j) += wgt * colours[static_cast<size_t>(ci)][static_cast<size_t>(j)] * x;
    }
    for (size_t ci = 0; ci < nc; ++ci) used += count[ci] >= kMinPixels;
    out.colours_matched = used;
    if (used < 2) return out;  // nothing to anchor a map: leave the frame alone
    const double lambda = kRidge * used;
    xtx += lambda * Eigen::Matrix4d::Identity();
    for (int j = 0; j < 3; ++j) xtt(j, j) += lambda;
    const Eigen::Matrix<double, 4, 3> m = xtx.ldlt().solve(xtt);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) map[static_cast<size_t>(4 * j + i)] = static_cast<float>(m(i, j));
  }
  // Trust check: the map may not move any corner of the colour cube far.
  for (int corner = 0; corner < 8; ++corner) {
    const float c[3] = {static_cast<float>(corner & 1), static_cast<float>((corner >> 1) & 1),
                        static_cast<float>((corner >> 2) & 1)};
    float o[3];
    apply(map, c, o);
    if (std::max({std::fabs(o[0] - c[0]), std::fabs(o[1] - c[1]), std::fabs(o[2] - c[2])}) > kMaxChange) return out;
  }
  // Shading: the gain of each flat pixel against the colour it shows, smoothed into a field
  // (normalised convolution: smoothed gains over smoothed evidence), divides the frame where
  // there is enough evidence. A darkened part is then its own colour again instead of looking
  // like a darker colour of the drawing, which the fit would otherwise grow over it.
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<float> gain_sum(n, 0.f), support(n, 0.f);
  for (int i : flat) {
    float c[3], g = 1;
    apply(map, rgba + static_cast<size_t>(i) * 4, c);
    const Match mt = classify(c, colours, g);
    if (mt.index < 0) continue;
    const auto& col = colours[static_cast<size_t>(mt.index)];
    if (is_white(col) || 0.299f * col[0] + 0.587f * col[1] + 0.114f * col[2] < kShadeLuma) continue;
    gain_sum[static_cast<size_t>(i)] = g;
    support[static_cast<size_t>(i)] = 1;
  }
  const int r = std::max(1, static_cast<int>(std::lround(0.5 * kShadeBox * std::max(w, h))));
  box_blur(gain_sum, w, h, r);
  box_blur(support, w, h, r);
  // Apply everywhere, then snap the flat pixels that clearly show one of the colours.
  std::vector<char> is_flat(n, 0);
  for (int i : flat) is_flat[static_cast<size_t>(i)] = 1;
  for (size_t i = 0; i < n; ++i) {
    float* p = rgba + i * 4;
    float c[3];
    apply(map, p, c);
    // Off the flats only the map's change of luma: a codec keeps a part's chroma smeared over
    // the light side of its edges (4:2:0), so the chroma there is not the flat colours' chroma
    // shifted, and the map, right on the flats, made it too bright (blue +0.013..0.016 on a
    // blurred bat's ramps, 0.2% of the ink: a thinner fit). Its luma shift is the flats'.
    if (!is_flat[i]) {
      const float l = 0.299f * (c[0] - p[0]) + 0.587f * (c[1] - p[1]) + 0.114f * (c[2] - p[2]);
      for (int j = 0; j < 3; ++j) c[j] = std::clamp(p[j] + l, 0.f, 1.f);
    }
    if (support[i] >= kShadeSupport) {
      const float g = gain_sum[i] / support[i];
      for (float& x : c) x = std::min(1.f, x / g);
      ++out.pixels_shaded;
    }
    if (is_flat[i]) {
      const Match mt = nearest(c, colours);
      if (mt.index >= 0) {
        for (int j = 0; j < 3; ++j) c[j] = colours[static_cast<size_t>(mt.index)][static_cast<size_t>(j)];
        ++out.pixels_snapped;
      }
    }
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
  }
  out.map = map;
  out.applied = true;
  return out;
}

}  // namespace svgm
