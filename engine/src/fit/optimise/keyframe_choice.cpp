// Keyframes from the target (see keyframe_choice.h).
#include "fit/optimise/keyframe_choice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "fit/optimise/inbetween.h"
#include "raster/raster_cl.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

const std::array<float, 4> kWhiteBg{1, 1, 1, 1};

// At most this many frame numbers are listed in the reason; the rest are counted.
constexpr size_t kListedFrames = 12;

}  // namespace

double loss_db(float loss, int frames, float w_image) {
  const double mse = static_cast<double>(loss) * std::max(1, frames) / std::max(1e-30f, w_image);
  return mse > 0 ? -10 * std::log10(mse) : 99.0;
}

int default_keyframe_budget(int keyframes, int source_frames) {
  return std::min(source_frames, 2 * keyframes);
}

KeyframeChoice choose_keyframes(const std::vector<int>& keys, const std::vector<double>& key_db,
                                const std::vector<int>& frames, const std::vector<double>& frame_db, int budget,
                                const KeyframeRule& rule) {
  if (keys.size() != key_db.size() || frames.size() != frame_db.size())
    throw Error("internal: keyframe scores do not match their frames");
  KeyframeChoice c;
  c.frames = keys;
  std::vector<std::pair<double, int>> missed;  // (dB, frame), worst first once sorted
  for (size_t j = 0; j < frames.size(); ++j) {
    const int f = frames[j];
    const double db = frame_db[j];
    if (c.worst_frame < 0 || db < c.worst_db) c.worst_frame = f, c.worst_db = db;
    // The keyframes either side (the frame is between two keyframes, or beyond the last).
    const auto hi = std::upper_bound(keys.begin(), keys.end(), f);
    double ref = std::numeric_limits<double>::infinity();
    if (hi != keys.end()) ref = std::min(ref, key_db[static_cast<size_t>(hi - keys.begin())]);
    if (hi != keys.begin()) ref = std::min(ref, key_db[static_cast<size_t>(hi - keys.begin() - 1)]);
    if (db < rule.good_db && db < ref - rule.margin_db) missed.push_back({db, f});
  }
  std::sort(missed.begin(), missed.end());
  for (const auto& [db, f] : missed) c.missed.push_back(f);
  std::sort(c.missed.begin(), c.missed.end());
  const size_t room = budget > static_cast<int>(keys.size()) ? static_cast<size_t>(budget) - keys.size() : 0;
  for (size_t j = 0; j < missed.size() && j < room; ++j) c.added.push_back(missed[j].second);
  if (c.added.empty() && c.missed.empty()) return c;
  std::sort(c.added.begin(), c.added.end());
  c.frames.insert(c.frames.end(), c.added.begin(), c.added.end());
  std::sort(c.frames.begin(), c.frames.end());
  std::string list;
  for (size_t j = 0; j < c.missed.size() && j < kListedFrames; ++j) list += (j ? ", " : "") + std::to_string(c.missed[j]);
  if (c.missed.size() > kListedFrames) list += " and " + std::to_string(c.missed.size() - kListedFrames) + " more";
  char tail[160];
  std::snprintf(tail, sizeof tail, " not predicted by the spline through the keyframes (worst: frame %d, %.1f dB)",
                c.worst_frame, c.worst_db);
  c.reason = "keyframes " + std::to_string(keys.size()) + " -> " + std::to_string(c.frames.size()) + ": frame" +
             (c.missed.size() > 1 ? "s " : " ") + list + (c.missed.size() > 1 ? " were" : " was") + tail;
  if (c.added.size() < c.missed.size())
    c.reason += "; " + std::to_string(c.missed.size() - c.added.size()) + " left to the spline by the budget of " +
                std::to_string(budget) + " keyframes";
  return c;
}

std::vector<double> measure_spline_frames(ClRuntime& rt, const RasterPlan& plan, const RenderSize& size,
                                          const std::vector<double>& key_points, const std::vector<double>& key_times,
                                          bool closed, int source_frames, const std::vector<int>& frames,
                                          const std::function<TargetFrames(const std::vector<int>&)>& load,
                                          const SplineLoss& loss) {
  std::vector<double> out(frames.size(), 0);
  if (frames.empty()) return out;
  const size_t per_key = static_cast<size_t>(plan.n_cp) * 2;
  const int N = std::max(2, source_frames);
  // The spline at every frame asked for: in_between samples the frames between keyframes,
  // every one when allowed as many as there are.
  std::vector<double> times;
  for (int f : frames) times.push_back(static_cast<double>(f) / (N - 1));
  const InBetween ib = in_between(key_points, key_times, per_key, times, N, closed);
  auto spline_at = [&](double t) -> const double* {
    for (size_t j = 0; j < ib.times.size(); ++j)
      if (std::fabs(ib.times[j] - t) < 1e-9) return &ib.points[j * per_key];
    throw Error("internal: no in-between at a frame between keyframes");
  };
  const int B = std::max(1, std::min(loss.batch, static_cast<int>(frames.size())));
  ClRaster raster(rt, plan, B, loss.render_sigma, loss.chroma_sigma, loss.chroma_weight);
  std::vector<int> order(frames.begin(), frames.end());
  std::sort(order.begin(), order.end());
  for (size_t first = 0; first < order.size(); first += static_cast<size_t>(B)) {
    const std::vector<int> batch(order.begin() + static_cast<std::ptrdiff_t>(first),
                                 order.begin() + static_cast<std::ptrdiff_t>(std::min(order.size(), first + B)));
    const int n = static_cast<int>(batch.size());
    const TargetFrames t = load(batch);
    std::vector<float> rgba(t.rgba);
    rgba.resize(static_cast<size_t>(B) * size.width * size.height * 4, 1.0f);
    std::vector<float> cp(static_cast<size_t>(B) * per_key, 0.0f);
    for (int j = 0; j < B; ++j) {
      const double* p = spline_at(static_cast<double>(batch[static_cast<size_t>(std::min(j, n - 1))]) / (N - 1));
      for (size_t i = 0; i < per_key; i += 2) {
        const Vec2 q = size.view.apply({p[i], p[i + 1]});
        cp[j * per_key + i] = static_cast<float>(q.x);
        cp[j * per_key + i + 1] = static_cast<float>(q.y);
      }
    }
    raster.set_active_frames(n);
    raster.set_targets(rgba);
    raster.set_control_points(cp);
    raster.enqueue_loss_and_gradient(loss.w_image, kWhiteBg);
    const std::vector<float> l = raster.read_frame_losses();
    for (int j = 0; j < n; ++j) {
      const size_t at = static_cast<size_t>(std::find(frames.begin(), frames.end(), batch[static_cast<size_t>(j)]) - frames.begin());
      out[at] = loss_db(l[static_cast<size_t>(j)], n, loss.w_image);
    }
  }
  return out;
}

std::vector<int> closest_sources(const std::vector<int>& prev, const TargetFrames& prev_target,
                                 const std::vector<int>& next, const TargetFrames& next_target) {
  const size_t px = static_cast<size_t>(prev_target.width) * prev_target.height * 4;
  if (next_target.width != prev_target.width || next_target.height != prev_target.height)
    throw Error("internal: keyframe targets of different sizes");
  std::vector<int> from(next.size(), 0);
  for (size_t k = 0; k < next.size(); ++k) {
    const auto same = std::find(prev.begin(), prev.end(), next[k]);
    if (same != prev.end()) {
      from[k] = static_cast<int>(same - prev.begin());
      continue;
    }
    const float* b = next_target.rgba.data() + k * px;
    double best = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < prev.size(); ++j) {
      const float* a = prev_target.rgba.data() + j * px;
      double d = 0;
      for (size_t i = 0; i < px && d < best; ++i) d += std::fabs(a[i] - b[i]);
      // Ties (a pose shown twice) go to the keyframe nearer in time.
      if (d < best || (d == best && std::abs(prev[j] - next[k]) < std::abs(prev[static_cast<size_t>(from[k])] - next[k])))
        best = d, from[k] = static_cast<int>(j);
    }
  }
  return from;
}

}  // namespace svgm
