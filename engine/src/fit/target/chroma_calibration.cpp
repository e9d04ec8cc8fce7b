// The chroma weight read off the video's first frame (see chroma_calibration.h).
#include "fit/target/chroma_calibration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>

namespace svgm {

TargetFrames still_target(const TargetFrames& target, int keyframes) {
  TargetFrames s;
  s.width = target.width;
  s.height = target.height;
  s.keyframes = keyframes;
  s.source_frames = keyframes;
  s.source_width = target.source_width;
  s.source_height = target.source_height;
  s.fps = target.fps;
  s.source_index.assign(static_cast<size_t>(keyframes), 0);
  const size_t px = static_cast<size_t>(target.width) * target.height;
  auto repeat = [&](const auto& v, size_t per, auto& out) {
    out.clear();
    for (int k = 0; k < keyframes; ++k) out.insert(out.end(), v.begin(), v.begin() + static_cast<std::ptrdiff_t>(per));
  };
  repeat(target.rgba, 4 * px, s.rgba);
  if (!target.raw.empty()) repeat(target.raw, 4 * px, s.raw);  // nothing reads it (compact_raw.h)
  repeat(target.mask, px, s.mask);
  repeat(target.sdf, px, s.sdf);
  return s;
}

namespace {

// How far keyframes 1.. of a finished still fit are from keyframe 0, the rest pose (pinned):
// the renders composited on white, mean squared difference over pixels and RGB channels; and
// the control points, RMS displacement in pixels.
ChromaCandidate drift_from_rest(Fitter& f, double weight) {
  ChromaCandidate c;
  c.weight = weight;
  const int K = f.active_keyframes();
  const int W = f.size().width, H = f.size().height;
  const size_t px = static_cast<size_t>(W) * H;
  const std::vector<float> r = f.render_keyframes();
  auto over_white = [&](int k, size_t p, int ch) {
    const float* q = &r[(static_cast<size_t>(k) * px + p) * 4];
    return static_cast<double>(q[ch]) + (1 - q[3]);
  };
  double se = 0;
  for (int k = 1; k < K; ++k)
    for (size_t p = 0; p < px; ++p)
      for (int ch = 0; ch < 3; ++ch) {
        const double d = over_white(k, p, ch) - over_white(0, p, ch);
        se += d * d;
      }
  c.drift = se / (3.0 * px * (K - 1));
  const std::vector<double> pts = f.keyframe_points_canvas();
  const RasterPlan& plan = f.raster_plan();
  const Affine& view = f.size().view;
  double d2 = 0;
  size_t n = 0;
  for (int k = 1; k < K; ++k)
    for (size_t path = 0; path < plan.path_cp_first.size(); ++path)
      for (int i = plan.path_cp_first[path]; i < plan.path_cp_first[path] + plan.path_cp_count[path]; ++i) {
        const size_t at = (static_cast<size_t>(k) * plan.n_cp + i) * 2, rest = static_cast<size_t>(i) * 2;
        const Vec2 a = view.apply({pts[at], pts[at + 1]}), b = view.apply({pts[rest], pts[rest + 1]});
        d2 += (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
        ++n;
      }
  c.drift_px = n ? std::sqrt(d2 / n) : 0;
  return c;
}

}  // namespace

ChromaCalibration calibrate_chroma_weight(ClRuntime& rt, const Scene& scene, const ChromaStage& coarse,
                                          const ChromaStage* fine, const ChromaCalibrationOptions& options) {
  ChromaCalibration cal;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    if (!coarse.target || coarse.target->keyframes < 1 || (fine && !fine->target) || options.keyframes < 2 ||
        options.weights.empty() || options.weights.front() != 1)
      throw std::runtime_error("nothing to calibrate on");
    // The still fit's options: the real fit's, with keyframe 0 the rest pose the others are
    // measured against, and nothing moving: no flow to track, no known motion to start from
    // (that is other frames').
    auto still_options = [&](const FitOptions& fit, int iterations) {
      FitOptions o = fit;
      o.iterations = iterations;
      o.pin_rest_keyframe = true;
      o.track = false;
      o.known_body.clear();
      o.known_maps.clear();
      return o;
    };
    auto run = [](Fitter& f) {
      while (!f.done())
        if (!std::isfinite(f.step().total())) throw std::runtime_error("the still fit's loss is not finite");
    };
    const TargetFrames still = still_target(*coarse.target, options.keyframes);
    const std::optional<TargetFrames> fine_still =
        fine ? std::optional<TargetFrames>(still_target(*fine->target, options.keyframes)) : std::nullopt;
    FitOptions o = still_options(coarse.options, options.iterations);
    FitOptions fo = fine ? still_options(fine->options, options.fine_iterations) : FitOptions{};
    for (double w : options.weights) {
      o.chroma_weight = fo.chroma_weight = w;
      Fitter f(rt, scene, still, o);
      run(f);
      if (f.active_keyframes() < 2) throw std::runtime_error("the still fit activated no free keyframe");
      ChromaCandidate c;
      if (fine) {
        // The refinement as fit_job runs it: the whole coarse fit, then every keyframe at the
        // finer width, where a video's chroma blocks are seen as such.
        Fitter g(rt, scene, *fine_still, fo);
        g.adopt_coarse(f, static_cast<double>(fine_still->width) / still.width);
        run(g);
        c = drift_from_rest(g, w);
      } else {
        c = drift_from_rest(f, w);
      }
      if (!std::isfinite(c.drift)) throw std::runtime_error("the drift is not finite");
      cal.candidates.push_back(c);
    }
    // The least drift wins, but a weight below 1 only when it beats 1 clearly (a tie within
    // noise keeps 1: a clean video is fitted exactly as with weight 1).
    const double at_one = cal.candidates.front().drift;
    double best = at_one;
    for (const ChromaCandidate& c : cal.candidates)
      if (c.weight != 1 && c.drift < (1 - options.margin) * at_one && c.drift < at_one - options.min_gain &&
          c.drift < best) {
        best = c.drift;
        cal.chosen = c.weight;
      }
  } catch (const std::exception& e) {
    cal.chosen = 1;
    cal.note = std::string("calibration failed (") + e.what() + "); fitted with weight 1";
  }
  cal.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return cal;
}

double sigma_at_source(double sigma, int width, int source_width) {
  if (!(width > 0 && source_width > 0) || !(sigma > 1)) return sigma;
  const double scale = static_cast<double>(source_width) / width;
  return std::sqrt(1 + (sigma * sigma - 1) * scale * scale);
}

ChromaGate chroma_calibration_gate(double luma_sigma, double chroma_sigma, int width, int source_width,
                                   double threshold) {
  ChromaGate g;
  g.threshold = threshold;
  g.measured_width = width;
  g.excess = sigma_at_source(chroma_sigma, width, source_width) - sigma_at_source(luma_sigma, width, source_width);
  // A NaN excess calibrates (the measurement says nothing).
  g.calibrate = !(g.excess < threshold);
  char buf[200];
  std::snprintf(buf, sizeof buf, "chroma sigma %.2f over luma sigma %.2f at %d px: excess %.2f at the video's %d px, %s %.2f",
                chroma_sigma, luma_sigma, width, g.excess, source_width, g.calibrate ? "at least" : "below", threshold);
  g.reason = buf;
  return g;
}

ChromaGate chroma_calibration_gate(const BlurMatch& match, int width, int source_width, double threshold) {
  return chroma_calibration_gate(match.chroma_luma_sigma, match.best_chroma_sigma, width, source_width, threshold);
}

}  // namespace svgm
