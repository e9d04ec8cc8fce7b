// The pixel ranker (see pixel_ranker.h for the signals, their thresholds and the score).
#include "rank/pixel_ranker.h"

#include "generators/candidates.h"
#include "rank/colour_coverage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numeric>
#include <set>

#include "svgmotion/error.h"

namespace svgm {

namespace {

using Rgb = std::array<double, 3>;

double clamp01(double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 1.0; }

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

std::string hex(const Rgb& c) {
  char buf[8];
  auto b = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", b(c[0]), b(c[1]), b(c[2]));
  return buf;
}

double dist(const Rgb& a, const Rgb& b) {
  const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
  return std::sqrt(x * x + y * y + z * z);
}

// Distance from p to the segment a -> b (a mixture of the two colours).
double dist_to_mixture(const Rgb& p, const Rgb& a, const Rgb& b) {
  const Rgb d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (dd < 1e-12) return dist(p, a);
  const double t =
      std::clamp(((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / dd, 0.0, 1.0);
  return dist(p, {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]});
}

// Distance from p to the segment c -> white (c blended with the white background).
double dist_to_white_blend(const Rgb& p, const Rgb& c) { return dist_to_mixture(p, c, {1, 1, 1}); }

// Pixels of `m` (W*H, 0/1) whose 8 neighbours (inside the image) are all set.
std::vector<uint8_t> core_of(const std::vector<uint8_t>& m, int W, int H) {
  std::vector<uint8_t> c(m.size(), 0);
  for (int y = 1; y + 1 < H; ++y)
    for (int x = 1; x + 1 < W; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1 && all; ++dy)
        for (int dx = -1; dx <= 1 && all; ++dx)
          all = m[static_cast<size_t>(y + dy) * W + (x + dx)] != 0;
      c[static_cast<size_t>(y) * W + x] = all ? 1 : 0;
    }
  return c;
}

// Total area of the 8-connected components of `far` that hold a core pixel and >= min_px pixels.
size_t blob_area(const std::vector<uint8_t>& far, const std::vector<uint8_t>& core, int W, int H,
                 size_t min_px) {
  std::vector<uint8_t> seen(far.size(), 0);
  std::vector<size_t> stack;
  size_t total = 0;
  for (size_t s = 0; s < far.size(); ++s) {
    if (!far[s] || seen[s]) continue;
    size_t n = 0;
    bool has_core = false;
    seen[s] = 1;
    stack.assign(1, s);
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      ++n;
      has_core = has_core || core[i];
      const int x = static_cast<int>(i % W), y = static_cast<int>(i / W);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= W || v >= H) continue;
          const size_t j = static_cast<size_t>(v) * W + u;
          if (far[j] && !seen[j]) {
            seen[j] = 1;
            stack.push_back(j);
          }
        }
    }
    if (has_core && n >= min_px) total += n;
  }
  return total;
}

}  // namespace

nlohmann::json CandidateScore::to_json() const {
  auto sig = [](const RankSignal& s) { return nlohmann::json{{"value", s.value}, {"reason", s.reason}}; };
  nlohmann::json j{{"name", name}};
  j["score"] = std::isfinite(score) ? nlohmann::json(score) : nlohmann::json(nullptr);
  if (!error.empty()) {
    j["error"] = error;
    return j;
  }
  j["signals"] = {{"colour_drift", sig(colour_drift)},
                  {"invented_content", sig(invented_content)},
                  {"continuity", sig(continuity)},
                  {"out_of_plane", sig(out_of_plane)},
                  {"motion", sig(motion)}};
  j["defects"] = defects;
  j["mean_motion"] = mean_motion;
  j["motion_penalty"] = motion_penalty;
  return j;
}

nlohmann::json Ranking::to_json() const {
  nlohmann::json c = nlohmann::json::array();
  for (const auto& s : candidates) c.push_back(s.to_json());
  return {{"chosen", chosen}, {"reason", reason}, {"candidates", c}};
}

namespace {

// Distinct palette colours (8-bit equality).
std::vector<Rgb> distinct_palette(const std::vector<Rgba>& palette_in) {
  std::vector<Rgb> pal;
  std::set<std::array<long, 3>> seen;
  for (const Rgba& c : palette_in) {
    const std::array<long, 3> key{std::lround(c.r * 255), std::lround(c.g * 255), std::lround(c.b * 255)};
    if (seen.insert(key).second) pal.push_back({c.r, c.g, c.b});
  }
  return pal;
}

// What the signals need of every frame.
struct FrameStats {
  std::vector<double> drift, invented, total;  // per frame
  std::vector<bool> has_fg;
  std::vector<std::vector<double>> area;       // per palette colour, per frame
  std::vector<std::vector<uint8_t>> fgs;       // per frame, the foreground mask
  std::vector<std::vector<int32_t>> labels;    // per frame, each pixel's palette colour (-1 none)
  FrameStats(size_t C, int K)
      : drift(K, 0.0), invented(K, 0.0), total(K, 0.0), has_fg(K, false),
        area(C, std::vector<double>(K, 0.0)), fgs(K), labels(K) {}
};

// The frame's own background: generated videos let the white page drift to an off-white
// tint, which is not foreground. The median of the border pixels, when it is near white.
Rgb frame_background(const float* f, int W, int H) {
  Rgb bg{1, 1, 1};
  std::array<std::vector<float>, 3> border;
  auto add = [&](int x, int y) {
    for (int ch = 0; ch < 3; ++ch) border[ch].push_back(f[4 * (static_cast<size_t>(y) * W + x) + ch]);
  };
  for (int x = 0; x < W; ++x) add(x, 0), add(x, H - 1);
  for (int y = 1; y + 1 < H; ++y) add(0, y), add(W - 1, y);
  Rgb med;
  for (int ch = 0; ch < 3; ++ch) {
    auto& v = border[ch];
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    med[ch] = v[v.size() / 2];
  }
  if (std::min({med[0], med[1], med[2]}) >= 0.85) bg = med;
  return bg;
}

// One frame's pixels against the palette.
struct FramePixels {
  std::vector<uint8_t> fg, far;     // foreground; no palette colour (nor its blend) near
  std::vector<float> dnear, dblend;  // distance to the nearest colour, and to its white blends
  std::vector<int32_t> label;       // the palette colour a pixel is nearest to, -1 none near
  size_t nfg = 0;
  explicit FramePixels(size_t P) : fg(P, 0), far(P, 0), dnear(P, 0.f), dblend(P, 0.f), label(P, -1) {}
};

// A pixel within `radius` of one of `colours`.
bool near_any(const Rgb& p, const std::vector<Rgb>& colours, double radius) {
  for (const Rgb& c : colours)
    if (dist(p, c) < radius) return true;
  return false;
}

// `rest`: colours the first frame already shows that no palette colour explains (below); a
// pixel near one of them is not "far", so it is no invented content.
FramePixels classify_pixels(const float* f, size_t P, const Rgb& bg, const std::vector<Rgb>& pal,
                            const std::vector<Rgb>& rest, const PixelRankOptions& o) {
  const size_t C = pal.size();
  const double bg_tolerance = 1 - o.white_threshold;
  FramePixels px(P);
  for (size_t i = 0; i < P; ++i) {
    const Rgb p{f[4 * i], f[4 * i + 1], f[4 * i + 2]};
    if (std::min({p[0], p[1], p[2]}) >= o.white_threshold) continue;
    if (std::max({std::abs(p[0] - bg[0]), std::abs(p[1] - bg[1]), std::abs(p[2] - bg[2])}) < bg_tolerance) continue;
    px.fg[i] = 1;
    ++px.nfg;
    double best = std::numeric_limits<double>::max(), expl = best;
    size_t bi = 0;
    for (size_t c = 0; c < C; ++c) {
      const double d = dist(p, pal[c]);
      if (d < best) best = d, bi = c;
      expl = std::min(expl, dist_to_white_blend(p, pal[c]));
    }
    px.dnear[i] = static_cast<float>(best);
    px.dblend[i] = static_cast<float>(expl);
    if (best < o.far_distance) px.label[i] = static_cast<int32_t>(bi);
    if (expl > o.far_distance && !near_any(p, rest, o.far_distance)) px.far[i] = 1;
  }
  return px;
}

// The colours of the first frame's off-palette areas (pixels whose 3x3 neighbourhood is all
// off-palette), as centres at least far_distance / 2 apart, in raster order, at most
// kMaxRestColours. A drawing's own translucent shapes blend with what lies under them into
// colours of no path: twemoji's fly draws its wings at opacity .5, and where they lie over its
// body every frame, the rest frame included, showed 7-8 % of the foreground off the palette, so
// every candidate was flagged "invented content" whatever its motion. Content is invented when
// it is new: a colour the rest frame already shows is the drawing's. (A candidate's first frame
// is the rest pose: the procedural provider's by construction, an image-to-video model's as it
// starts from the image.) A first frame too far off the palette to describe with
// kMaxRestColours colours keeps the rest of its off-palette pixels far.
constexpr size_t kMaxRestColours = 32;

std::vector<Rgb> rest_colours(const TargetFrames& t, const Rgb& bg, const std::vector<Rgb>& pal,
                              const PixelRankOptions& o) {
  const size_t P = static_cast<size_t>(t.width) * t.height;
  const FramePixels px = classify_pixels(t.raw.data(), P, bg, pal, {}, o);
  const std::vector<uint8_t> core = core_of(px.far, t.width, t.height);
  std::vector<Rgb> centres;
  for (size_t i = 0; i < P && centres.size() < kMaxRestColours; ++i) {
    if (!core[i]) continue;
    const Rgb p{t.raw[4 * i], t.raw[4 * i + 1], t.raw[4 * i + 2]};
    if (!near_any(p, centres, o.far_distance / 2)) centres.push_back(p);
  }
  return centres;
}

// Frame k's foreground, colour areas, drift and invented content, into `st`.
void measure_frame(const TargetFrames& t, int k, size_t P, const std::vector<Rgb>& pal,
                   const std::vector<Rgb>& rest, const PixelRankOptions& o, FrameStats& st) {
  const int W = t.width, H = t.height;
  const float* f = &t.raw[P * 4 * k];
  const Rgb bg = frame_background(f, W, H);
  FramePixels px = classify_pixels(f, P, bg, pal, rest, o);
  std::vector<double> soft(pal.size(), 0.0);
  add_soft_colour_areas(f, W, H, bg, px.fg, px.label, px.dnear, pal, o.far_distance, soft);
  for (size_t c = 0; c < pal.size(); ++c) st.area[c][k] = soft[c];
  const size_t nfg = px.nfg;
  st.total[k] = static_cast<double>(nfg);
  st.has_fg[k] = nfg > 0;
  if (nfg > 0) {
    // Drift: the median over the foreground of each pixel's distance to the palette; a pixel
    // on an edge (not interior) may also be a palette colour's blend with white (anti-
    // aliasing, and the colour bleeding of 4:2:0 video). Not the interior alone: a line
    // drawing's strokes are one or two pixels wide at the analysis size, so its few interior
    // pixels are where strokes cross (mixtures of two colours), and a clean render of it
    // measured 0.16 from its palette.
    const std::vector<uint8_t> interior = core_of(px.fg, W, H);
    std::vector<float> d;
    for (size_t i = 0; i < P; ++i)
      if (px.fg[i]) d.push_back(std::min(interior[i] ? px.dnear[i] : std::min(px.dnear[i], px.dblend[i]), static_cast<float>(o.far_distance)));
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    st.drift[k] = d[d.size() / 2];
    st.invented[k] = static_cast<double>(blob_area(px.far, core_of(px.far, W, H), W, H, 4)) / nfg;
  }
  st.fgs[k] = std::move(px.fg);
  st.labels[k] = std::move(px.label);
}

// Colour drift.
RankSignal colour_drift_signal(const FrameStats& st, int K) {
  RankSignal r;
  std::vector<int> ks;
  for (int k = 0; k < K; ++k)
    if (st.has_fg[k]) ks.push_back(k);
  if (ks.empty()) {
    r = {0, "no foreground"};
  } else {
    const std::vector<double>& drift = st.drift;
    double mean = 0;
    for (int k : ks) mean += drift[k];
    mean /= static_cast<double>(ks.size());
    const double growth = drift[ks.back()] - drift[ks.front()];
    r.value = clamp01(std::max((mean - 0.02) / 0.1, growth / 0.08));
    r.reason = fmt("foreground is %.3f from the palette (median, mean over frames), %.3f "
                   "in the first frame and %.3f in the last", mean, drift[ks.front()], drift[ks.back()]);
  }
  return r;
}

// Invented content.
RankSignal invented_content_signal(const FrameStats& st) {
  RankSignal r;
  const auto it = std::max_element(st.invented.begin(), st.invented.end());
  const double f = *it;
  r.value = clamp01((f - 0.005) / 0.03);
  r.reason =
      f > 0 ? fmt("off-palette blobs cover up to %.1f%% of the foreground (frame %.0f)", 100 * f,
                  static_cast<double>(it - st.invented.begin()))
            : "no off-palette blobs";
  return r;
}

double foreground_spread(const FrameStats& st, int k, int W, int H);

// What a flat change of the whole figure takes of a colour's area when the figure's spread
// (foreground_spread) changes by the factor `rho` (at most 1): a turn about its vertical axis
// narrows every filled part with it (rho) and pushes its parts over one another, which hides
// more of the ones behind. Measured on an openmoji water buffalo turning round: where its spread
// fell to 0.61 of the frame before, a leg behind another kept 0.35 of its area, the body 0.51
// (outlines keep their width and more). rho squared bounds what such a turn takes; a change with
// no change of the figure's spread (a bend cutting a hand, a blob) is judged as it is.
double flat_change_floor(double rho) { return rho * rho; }

// Continuity per palette colour (soft areas, colour_coverage.h), each change measured against
// what the change of the whole figure's spread explains (flat_change_floor); `appear_vanish`
// receives the larger of its appearing and vanishing parts (which explain out-of-plane area
// changes).
RankSignal continuity_signal(const FrameStats& st, const std::vector<Rgb>& pal, const std::vector<double>& spread, double mean_fg,
                             int K, double& appear_vanish) {
  RankSignal r;
  const size_t C = pal.size();
  const double significant = std::max(8.0, 0.02 * mean_fg);
  // The floor of what the figure's change from frame a to frame b explains of a colour's change
  // in the same direction (1: none).
  auto floor_of = [&](int a, int b) {
    const double lo = std::min(spread[a], spread[b]), hi = std::max(spread[a], spread[b]);
    return lo > 0 ? flat_change_floor(lo / hi) : 1.0;
  };
  double vanish = 0, appear = 0, jump = 0;
  std::string vr, ar, jr;
  for (size_t c = 0; c < C; ++c) {
    const auto& a = st.area[c];
    const double a0 = a[0];
    // The least of the colour's areas, each raised by what the figure's narrowing since frame 0
    // explains; the most, each lowered by what its widening explains.
    double least = std::numeric_limits<double>::max(), most = 0;
    int kmin = 0;
    for (int k = 0; k < K; ++k) {
      const double f = floor_of(0, k);
      const double low = spread[k] <= spread[0] ? a[k] / f : a[k], high = spread[k] >= spread[0] ? a[k] * f : a[k];
      if (low < least) least = low, kmin = k;
      most = std::max(most, high);
    }
    const double amax = *std::max_element(a.begin(), a.end());
    if (a0 >= significant) {
      const double v = clamp01((kRankVanishRatio - least / a0) / 0.25);
      if (vr.empty() || v > vanish) {
        vanish = std::max(vanish, v);
        vr = hex(pal[c]) + fmt(" falls from %.0f px to %.0f px (frame %.0f)", a0, a[kmin], kmin);
      }
    }
    if (amax >= significant && most > 0) {
      const double v = clamp01((kRankVanishRatio - a0 / most) / 0.25);
      if (v > appear) {
        appear = v;
        ar = hex(pal[c]) + fmt(" appears: %.0f px in frame 0, up to %.0f px later", a0, amax);
      }
    }
    for (int k = 0; k + 1 < K; ++k) {
      const double hi = std::max(a[k], a[k + 1]), lo = std::min(a[k], a[k + 1]);
      if (hi < significant) continue;
      const bool with_figure = (a[k + 1] < a[k]) == (spread[k + 1] < spread[k]);
      const double f = with_figure ? floor_of(k, k + 1) : 1.0;
      const double j = std::max(0.0, 1 - lo / hi / f);
      if (j > jump) {
        jump = j;
        jr = hex(pal[c]) + fmt(" jumps from %.0f px to %.0f px (frame %.0f)", a[k], a[k + 1], k + 1) +
             (f < 1 ? fmt(", the figure's spread x%.2f", spread[k + 1] / spread[k]) : "");
      }
    }
  }
  const double jv = clamp01((jump - 0.35) / 0.4);
  appear_vanish = std::max(vanish, appear);
  r.value = std::max(appear_vanish, jv);
  if (r.value <= 0)
    r.reason = fmt("palette colours keep their areas (largest frame-to-frame change %.0f%% beyond the figure's own)", 100 * jump);
  else if (vanish >= appear && vanish >= jv)
    r.reason = "a colour vanishes: " + vr;
  else if (appear >= jv)
    r.reason = "a colour appears suddenly: " + ar;
  else
    r.reason = "a colour's area changes suddenly: " + jr;
  return r;
}

// The foreground's box in frame k: x0, y0, x1, y1 (exclusive); x1 == 0 when there is none.
std::array<int, 4> foreground_box(const FrameStats& st, int k, int W, int H) {
  std::array<int, 4> b{W, H, 0, 0};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (st.fgs[k][static_cast<size_t>(y) * W + x]) b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x + 1), std::max(b[3], y + 1)};
  return b;
}

// How much of frame k is frame 0 stretched into frame k's foreground box (each axis scaled, the
// horizontal one mirrored when `mirror`): of the pixels foreground in either, the share whose
// palette colour is the same in both.
double stretch_agreement(const FrameStats& st, int k, int W, const std::array<int, 4>& b0,
                         const std::array<int, 4>& bk, bool mirror) {
  const double sx = static_cast<double>(b0[2] - b0[0]) / (bk[2] - bk[0]), sy = static_cast<double>(b0[3] - b0[1]) / (bk[3] - bk[1]);
  size_t either = 0, same = 0;
  for (int y = bk[1]; y < bk[3]; ++y)
    for (int x = bk[0]; x < bk[2]; ++x) {
      const double u = mirror ? bk[2] - (x + 0.5) : x + 0.5 - bk[0];
      const int x0 = std::clamp(b0[0] + static_cast<int>(u * sx), b0[0], b0[2] - 1);
      const int y0 = std::clamp(b0[1] + static_cast<int>((y + 0.5 - bk[1]) * sy), b0[1], b0[3] - 1);
      const size_t i = static_cast<size_t>(y) * W + x, j = static_cast<size_t>(y0) * W + x0;
      const bool a = st.fgs[k][i] != 0, c = st.fgs[0][j] != 0;
      if (!a && !c) continue;
      ++either;
      same += a && c && st.labels[k][i] == st.labels[0][j];
    }
  return either > 0 ? static_cast<double>(same) / static_cast<double>(either) : 0.0;
}

// The spread of frame k's foreground: the square root of the determinant of its pixels'
// covariance (pixels squared). A flat map of the frame by a linear part A multiplies it by
// |det A|, whatever A's rotation or shear: the area a flat figure's changes by.
double foreground_spread(const FrameStats& st, int k, int W, int H) {
  double n = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (st.fgs[k][static_cast<size_t>(y) * W + x]) n += 1, sx += x, sy += y, sxx += 1.0 * x * x, syy += 1.0 * y * y, sxy += 1.0 * x * y;
  if (n < 2) return 0;
  const double mx = sx / n, my = sy / n;
  const double cxx = sxx / n - mx * mx, cyy = syy / n - my * my, cxy = sxy / n - mx * my;
  return std::sqrt(std::max(0.0, cxx * cyy - cxy * cxy));
}

// How far frame k's mix of palette colours is from frame 0's: half the sum over colours of the
// difference of their shares of the counted colour area (0: the same mix, 1: no colour shared).
double colour_mix_distance(const FrameStats& st, int k) {
  double t0 = 0, tk = 0;
  for (const auto& a : st.area) t0 += a[0], tk += a[k];
  if (t0 <= 0 || tk <= 0) return 1;
  double d = 0;
  for (const auto& a : st.area) d += std::abs(a[k] / tk - a[0] / t0);
  return 0.5 * d;
}

// The share of frames 1..K-1 that are a flat change of frame 0, in one of two ways:
//  - frame 0 stretched (a hop's squash) or turned about its vertical axis (its width scaled,
//    mirrored past edge on: a flat figure's pirouette): their foreground area is frame 0's times
//    the stretch of its box (within kFlatArea) and their colours agree with frame 0's stretched
//    into their box (kFlatAgreement);
//  - frame 0 mapped in the plane any other way as well (turned about its vertical axis while it
//    also twists, bends or rocks: a tornado that "twists and whirls", its top swung 10 degrees
//    against its base as it turns): their foreground area is frame 0's times the change of its
//    spread (foreground_spread, within kFlatArea) and every colour keeps its share of the
//    colours' area (colour_mix_distance at most kFlatMix). Pixel by pixel the first test cannot
//    see it: no stretch of the first frame's box lays a bent figure on itself, and a line
//    drawing's bands, an outline a pixel or two wide over its colour's stroke, agreed at 0.83
//    on a frame that was the first one again.
// Such changes of area are the figure's own, in the plane: the fitter follows them with its
// control points. Parts that grow or shrink inside a box that does not (a 3D turn showing other
// sides) change the area alone, and the mix of colours with it.
double flat_stretch_share(const FrameStats& st, int K, int W, int H) {
  constexpr double kFlatAgreement = 0.75, kFlatArea = 0.15, kFlatMix = 0.15;
  const std::array<int, 4> b0 = foreground_box(st, 0, W, H);
  if (K < 2 || b0[2] <= b0[0] || st.total[0] <= 0) return 0;
  const double box0 = static_cast<double>(b0[2] - b0[0]) * (b0[3] - b0[1]);
  const double spread0 = foreground_spread(st, 0, W, H);
  int flat = 0;
  for (int k = 1; k < K; ++k) {
    const std::array<int, 4> bk = foreground_box(st, k, W, H);
    if (bk[2] <= bk[0]) continue;
    const double expected = st.total[0] * (bk[2] - bk[0]) * (bk[3] - bk[1]) / box0;
    if (std::abs(st.total[k] / expected - 1) <= kFlatArea &&
        std::max(stretch_agreement(st, k, W, b0, bk, false), stretch_agreement(st, k, W, b0, bk, true)) >= kFlatAgreement) {
      ++flat;
      continue;
    }
    const double spread_k = foreground_spread(st, k, W, H);
    if (spread0 <= 0 || spread_k <= 0) continue;
    const double mapped = st.total[0] * spread_k / spread0;
    flat += std::abs(st.total[k] / mapped - 1) <= kFlatArea && colour_mix_distance(st, k) <= kFlatMix;
  }
  return static_cast<double>(flat) / (K - 1);
}

// Out-of-plane motion: total foreground area changes that no appearing/vanishing explains, nor
// a flat stretch or turn of the figure (flat_stretch_share).
RankSignal out_of_plane_signal(const FrameStats& st, double mean_fg, int K, int W, int H, double appear_vanish) {
  RankSignal r;
  double var = 0;
  for (double a : st.total) var += (a - mean_fg) * (a - mean_fg);
  const double rel = mean_fg > 0 ? std::sqrt(var / K) / mean_fg : 0.0;
  const double flat = rel > 0.08 ? flat_stretch_share(st, K, W, H) : 0.0;
  r.value = clamp01((rel - 0.08) / 0.22) * (1 - appear_vanish) * (1 - flat);
  r.reason = fmt("foreground area varies by %.1f%% (relative std)", 100 * rel) +
             (appear_vanish > 0 && rel > 0.08 ? ", explained by colours appearing/vanishing" : "") +
             (flat > 0 ? fmt(", %.0f%% of the frames a flat stretch or turn of the first", 100 * flat) : "");
  return r;
}

// The whole-frame shifts the chaos test tries: up to this share of the frame's longer side (a
// shake raised to the visible floor moves 3-8 % of the canvas between keyframes), searched first
// on a grid of this many samples across.
constexpr double kShiftReach = 0.2;
constexpr int kShiftCoarse = 64;

// The mean absolute colour difference between frame ka and frame kb read `shift` pixels away
// (kb's pixel at (x + dx, y + dy) against ka's at (x, y)), over the pixels foreground in either
// and inside both, every `step`-th row and column.
double shifted_diff(const TargetFrames& t, const FrameStats& st, int ka, int kb, std::array<int, 2> shift, int step) {
  const int W = t.width, H = t.height, dx = shift[0], dy = shift[1];
  const size_t P = static_cast<size_t>(W) * H;
  const float* a = &t.raw[P * 4 * ka];
  const float* b = &t.raw[P * 4 * kb];
  double d = 0;
  size_t n = 0;
  for (int y = std::max(0, -dy); y < std::min(H, H - dy); y += step)
    for (int x = std::max(0, -dx); x < std::min(W, W - dx); x += step) {
      const size_t i = static_cast<size_t>(y) * W + x, j = static_cast<size_t>(y + dy) * W + (x + dx);
      if (!st.fgs[ka][i] && !st.fgs[kb][j]) continue;
      ++n;
      d += (std::abs(a[4 * i] - b[4 * j]) + std::abs(a[4 * i + 1] - b[4 * j + 1]) + std::abs(a[4 * i + 2] - b[4 * j + 2])) / 3.0;
    }
  return n > 0 ? d / static_cast<double>(n) : 0.0;
}

// The difference of frames ka and kb once kb is moved back by the whole-frame shift (within
// kShiftReach of the frame's longer side) that matches ka best: searched on every
// kShiftCoarse-th pixel in shifts of as many pixels, then to the pixel around the best. A figure
// shaken or carried along rigidly changes most of its pixels between two frames (a twemoji alarm
// clock shaken 3 % of the canvas between keyframes: a mean difference of 0.40) while each frame
// is the one before, moved: what a tracker follows and a fitter's homography reproduces, no chaos.
double aligned_diff(const TargetFrames& t, const FrameStats& st, int ka, int kb) {
  const int step = std::max(1, std::max(t.width, t.height) / kShiftCoarse);
  const int reach = static_cast<int>(kShiftReach * std::max(t.width, t.height)) / step * step;
  std::array<int, 2> best{0, 0};
  double low = shifted_diff(t, st, ka, kb, best, step);
  for (int dy = -reach; dy <= reach; dy += step)
    for (int dx = -reach; dx <= reach; dx += step)
      if (const double d = shifted_diff(t, st, ka, kb, {dx, dy}, step); d < low) low = d, best = {dx, dy};
  const std::array<int, 2> coarse = best;
  low = shifted_diff(t, st, ka, kb, best, 1);
  for (int dy = coarse[1] - step + 1; dy < coarse[1] + step; ++dy)
    for (int dx = coarse[0] - step + 1; dx < coarse[0] + step; ++dx)
      low = std::min(low, shifted_diff(t, st, ka, kb, {dx, dy}, 1));
  return low;
}

// Motion amount; `motion_defect` receives the defect's name when there is one, `mean` the mean
// frame difference (how much a viewer sees move, for rank()).
RankSignal motion_signal(const TargetFrames& t, const FrameStats& st, size_t P, int K,
                         std::string& motion_defect, double& mean) {
  RankSignal r;
  const std::vector<std::vector<uint8_t>>& fgs = st.fgs;
  // Over the pixels foreground in frame ka or kb: the mean absolute colour difference, and the
  // fraction of them whose colour changed by more than 0.15 (moved, not codec noise).
  auto frame_diff = [&](int ka, int kb, double* moved) -> double {
    const float* a = &t.raw[P * 4 * ka];
    const float* b = &t.raw[P * 4 * kb];
    double d = 0;
    size_t n = 0, changed = 0;
    for (size_t i = 0; i < P; ++i) {
      if (!fgs[ka][i] && !fgs[kb][i]) continue;
      ++n;
      const double di = (std::abs(a[4 * i] - b[4 * i]) + std::abs(a[4 * i + 1] - b[4 * i + 1]) +
                         std::abs(a[4 * i + 2] - b[4 * i + 2])) / 3.0;
      d += di;
      changed += di > 0.15;
    }
    if (moved) *moved = n > 0 ? static_cast<double>(changed) / static_cast<double>(n) : 0.0;
    return n > 0 ? d / static_cast<double>(n) : 0.0;
  };
  double sum = 0;
  int pairs = 0;
  for (int k = 0; k + 1 < K; ++k) sum += frame_diff(k, k + 1, nullptr), ++pairs;
  // Range of motion: the largest share of the foreground that has moved away from the first
  // frame. Consecutive frames of a smooth 24 fps wave differ by a few thousandths and a waving
  // hand is a few percent of a figure, so neither a consecutive nor a whole-figure mean tells
  // a small real motion from a still clip; the share of pixels that really changed does.
  double range = 0;
  for (int k = 1; k < K; ++k) {
    double moved = 0;
    frame_diff(0, k, &moved);
    range = std::max(range, moved);
  }
  const double m = pairs > 0 ? sum / pairs : 0.0;
  mean = m;
  // Large frame differences are chaos only when no shift of the frame before explains them.
  double aligned = m;
  if (m > 0.25) {
    aligned = 0;
    for (int k = 0; k + 1 < K; ++k) aligned += aligned_diff(t, st, k, k + 1);
    aligned /= pairs;
  }
  if (K < 2) {
    r = {1, "a single frame"};
    motion_defect = "no motion";
  } else if (range < 0.005) {
    r = {clamp01((0.005 - range) / 0.004),
         fmt("nearly static: at most %.2f%% of the foreground moves away from the first frame", 100 * range)};
    motion_defect = "no motion";
  } else if (aligned > 0.25) {
    r = {clamp01((aligned - 0.25) / 0.3),
         fmt("large, chaotic motion: mean frame difference %.3f on the foreground (%.3f with each frame shifted to match the one before)", m,
             aligned)};
    motion_defect = "chaotic motion";
  } else {
    r = {0, fmt("calm motion: mean frame difference %.4f", m) +
                (aligned < m ? fmt(" (%.4f with each frame shifted to match the one before)", aligned) : "") +
                fmt(", up to %.1f%% of the foreground moved", 100 * range)};
  }
  return r;
}

}  // namespace

CandidateScore score_candidate(const TargetFrames& t, const std::vector<Rgba>& palette_in,
                               const PixelRankOptions& o) {
  const int W = t.width, H = t.height, K = t.keyframes;
  if (W <= 0 || H <= 0 || K <= 0) throw Error("pixel ranker: empty frames");
  const size_t P = static_cast<size_t>(W) * H;
  if (t.raw.size() != P * K * 4)
    throw Error("pixel ranker: frames hold " + std::to_string(t.raw.size()) + " floats, not " +
                std::to_string(P * K * 4));
  const std::vector<Rgb> pal = distinct_palette(palette_in);
  if (pal.empty()) throw Error("pixel ranker: the palette has no colours");

  FrameStats st(pal.size(), K);
  const std::vector<Rgb> rest = rest_colours(t, frame_background(t.raw.data(), W, H), pal, o);
  for (int k = 0; k < K; ++k) measure_frame(t, k, P, pal, rest, o, st);

  CandidateScore s;
  const double mean_fg = std::accumulate(st.total.begin(), st.total.end(), 0.0) / K;
  s.colour_drift = colour_drift_signal(st, K);
  s.invented_content = invented_content_signal(st);
  double appear_vanish = 0;
  std::vector<double> spread(K);
  for (int k = 0; k < K; ++k) spread[k] = foreground_spread(st, k, W, H);
  s.continuity = continuity_signal(st, pal, spread, mean_fg, K, appear_vanish);
  s.out_of_plane = out_of_plane_signal(st, mean_fg, K, W, H, appear_vanish);
  std::string motion_defect;
  s.motion = motion_signal(t, st, P, K, motion_defect, s.mean_motion);

  const RankSignal* sig[5] = {&s.colour_drift, &s.invented_content, &s.continuity, &s.out_of_plane, &s.motion};
  const char* names[5] = {"colour drift", "invented content", "continuity", "out-of-plane motion", nullptr};
  double wsum = 0;
  for (int i = 0; i < 5; ++i) {
    s.score += kPixelRankWeights[i] * sig[i]->value;
    wsum += kPixelRankWeights[i];
    if (sig[i]->value >= o.defect_threshold) s.defects.push_back(names[i] ? names[i] : motion_defect);
  }
  s.score /= wsum;
  return s;
}

Ranking rank(std::vector<CandidateScore> scores) {
  auto readable = [](const CandidateScore& c) { return c.error.empty() && std::isfinite(c.score); };
  double most = 0;
  for (const auto& c : scores)
    if (readable(c) && c.defects.empty()) most = std::max(most, c.mean_motion);
  for (auto& c : scores)
    c.motion_penalty = readable(c) && c.defects.empty() && most > 0 ? kMotionPreference * (1 - c.mean_motion / most) : 0.0;
  std::stable_sort(scores.begin(), scores.end(), [&](const CandidateScore& a, const CandidateScore& b) {
    const bool ea = !readable(a), eb = !readable(b);
    if (ea != eb) return eb;
    if (ea) return a.name < b.name;
    if (a.defects.empty() != b.defects.empty()) return a.defects.empty();
    const double ka = a.score + a.motion_penalty, kb = b.score + b.motion_penalty;
    if (ka != kb) return ka < kb;
    return a.name < b.name;
  });
  if (scores.empty() || !readable(scores.front()))
    throw Error(scores.empty() ? "pixel ranker: no candidates"
                               : "pixel ranker: no readable candidate (" + scores.front().name + ": " +
                                     scores.front().error + ")");
  Ranking r;
  r.candidates = std::move(scores);
  const CandidateScore& b = r.candidates.front();
  r.chosen = b.name;
  size_t n = 0;
  for (const auto& c : r.candidates) n += c.error.empty() ? 1 : 0;
  r.reason = fmt("lowest score %.3f of %.0f candidate", b.score + b.motion_penalty, static_cast<double>(n)) + (n == 1 ? "" : "s");
  if (b.motion_penalty >= 0.0005) r.reason += fmt(" (%.3f, and %.3f for moving less than the most moving)", b.score, b.motion_penalty);
  if (r.candidates.size() > 1 && r.candidates[1].error.empty())
    r.reason += " (next: " + r.candidates[1].name + fmt(", %.3f)", r.candidates[1].score + r.candidates[1].motion_penalty);
  if (b.defects.empty()) {
    r.reason += "; no defects";
  } else {
    r.reason += "; defects:";
    for (size_t i = 0; i < b.defects.size(); ++i) r.reason += (i ? ", " : " ") + b.defects[i];
  }
  return r;
}

CandidateScore score_candidate_file(const std::filesystem::path& video, const std::vector<Rgba>& palette,
                                    const PixelRankOptions& o) {
  const TargetInfo info = probe_target(video);
  if (info.width <= 0 || info.height <= 0 || info.frames <= 0) throw Error(video.string() + ": no frames");
  const int w = std::max(1, std::min(info.width, o.analysis_width));
  const int h = std::max(1, static_cast<int>(std::lround(static_cast<double>(info.height) * w / info.width)));
  TargetOptions to;
  to.keyframes = std::clamp(info.frames, 1, std::max(1, o.keyframes));
  to.white_threshold = o.white_threshold;
  CandidateScore s = score_candidate(load_target(video, w, h, to), palette, o);
  s.name = video.filename().string();
  return s;
}

Ranking rank_directory(const std::filesystem::path& dir, const std::vector<Rgba>& palette,
                       const PixelRankOptions& o,
                       const std::function<bool(double, const std::string&)>& progress,
                       const std::function<int(const std::string&)>& keyframes_of) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(dir.string() + ": no candidates folder");
  const std::vector<fs::path> entries = list_candidates(dir);
  if (entries.empty()) throw Error(dir.string() + ": no candidate videos");
  if (palette.empty()) throw Error("pixel ranker: the palette has no colours");
  std::vector<CandidateScore> scores;
  for (size_t i = 0; i < entries.size(); ++i) {
    const std::string name = entries[i].filename().string();
    if (progress && !progress(static_cast<double>(i) / entries.size(), "scoring " + name))
      throw Error("cancelled");
    try {
      PixelRankOptions oi = o;
      if (keyframes_of)
        if (const int k = keyframes_of(name); k > 0) oi.keyframes = k;
      CandidateScore s = score_candidate_file(entries[i], palette, oi);
      s.name = name;
      scores.push_back(std::move(s));
    } catch (const std::exception& e) {
      CandidateScore s;
      s.name = name;
      s.score = std::numeric_limits<double>::infinity();
      s.error = e.what();
      scores.push_back(std::move(s));
    }
  }
  if (progress) progress(1.0, "ranked");
  return rank(std::move(scores));
}

}  // namespace svgm
