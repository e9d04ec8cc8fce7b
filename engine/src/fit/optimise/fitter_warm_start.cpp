// The fitter's warm starts (see fitter.h, warm_start.h, field_warm_start.h): a newly active
// keyframe carried from the one before toward its own target by the tracked (or known) motion
// of its points, each start kept only when it fits the keyframe better.
#include "fit/optimise/fitter.h"

#include <algorithm>
#include <cmath>

#include "fit/optimise/field_warm_start.h"
#include "fit/optimise/fitter_internal.h"
#include "fit/optimise/warm_start.h"
#include "geometry/rigid_bodies.h"
#include "svgmotion/error.h"

namespace svgm {

using namespace fitter_internal;

namespace {

// The source keyframe's render (premultiplied, composited on white) and keyframe k's target,
// both in grey: what the point tracker compares.
void grey_frames(const std::vector<float>& img, const float* target, std::vector<uint8_t>& prev,
                 std::vector<uint8_t>& next) {
  auto grey = [](float r, float g, float b) {
    return static_cast<uint8_t>(std::clamp(255.f * (0.299f * r + 0.587f * g + 0.114f * b) + 0.5f, 0.f, 255.f));
  };
  for (size_t p = 0; p < prev.size(); ++p) {
    const float* c = &img[p * 4];
    prev[p] = grey(c[0] + 1 - c[3], c[1] + 1 - c[3], c[2] + 1 - c[3]);
    const float* t = &target[p * 4];
    next[p] = grey(t[0], t[1], t[2]);
  }
}

// The tracker stage's flow between the target keyframes, at the fitted points.
PointTracks flow_tracks_at(const FlowField& flow, const std::vector<uint8_t>& prev, int W, int H,
                           const std::vector<Vec2>& from) {
  PointTracks tracks;
  tracks.to = from;
  tracks.weight.assign(from.size(), 0.0);
  for (size_t j = 0; j < from.size(); ++j) {
    double dx, dy, w;
    flow.sample(from[j].x, from[j].y, W, H, &dx, &dy, &w);
    tracks.to[j] = from[j] + Vec2{dx, dy};
    tracks.weight[j] = w;
  }
  tracks.isotropy = window_isotropy(prev, W, H, from, 7);  // as track_points' 15 px window
  return tracks;
}

}  // namespace

void Fitter::warm_start(int k, int src) {
  auto& q = rt_.queue();
  const int W = size_.width, H = size_.height;
  // The source keyframe as fitted so far (the previous one, or k itself as copied): its
  // render and its control points.
  enqueue_motion(src + 1);
  // That keyframe alone (16 bytes per pixel, not per pixel and keyframe up to src).
  const auto img = raster_->render_frames(src, 1, kWhite);
  std::vector<float> cp(static_cast<size_t>(plan_.n_cp) * 2);
  q.enqueueReadBuffer(raster_->cp_buffer(), CL_TRUE, static_cast<size_t>(src) * plan_.n_cp * 2 * sizeof(float),
                      cp.size() * sizeof(float), cp.data());
  std::vector<uint8_t> prev(static_cast<size_t>(W) * H), next(prev.size());
  // Keyframe k's target: from the whole clip, or read as the loss reads it when its holder
  // keeps the frames packed (read_targets_from: `bench fit`), one frame's floats (1 MB at 512 px).
  std::vector<float> packed_frame;
  const float* target_k = nullptr;
  if (target_.rgba.empty()) {
    packed_frame.resize(static_cast<size_t>(H) * W * 4);
    raster_->target_frame(k, packed_frame.data());
    target_k = packed_frame.data();
  } else {
    if (target_.rgba.size() < static_cast<size_t>(k + 1) * H * W * 4)
      throw Error("internal: a warm start without its target's frames (set aside)");
    target_k = &target_.rgba[static_cast<size_t>(k) * H * W * 4];
  }
  grey_frames(img, target_k, prev, next);
  std::vector<Vec2> from;
  std::vector<int> index;
  for (int i = 0; i < plan_.n_cp; ++i)
    if (fplan_.cp_group[i] >= 0 && fplan_.cp_offset[i] == i) {
      from.push_back({cp[2 * i], cp[2 * i + 1]});
      index.push_back(i);
    }
  PointTracks tracks;
  if (src == k - 1 && k < static_cast<int>(flows_.size()) && flows_[k].grid > 0) {
    tracks = flow_tracks_at(flows_[k], prev, W, H, from);
  } else {
    tracks = track_points(prev, next, W, H, from);
  }

  // Per group: the similarity the tracks show, composed into the copied homography.
  const size_t pb = static_cast<size_t>(G_) * kMotionParams;
  std::vector<float> copied(pb);
  q.enqueueReadBuffer(params_, CL_TRUE, k * pb * sizeof(float), pb * sizeof(float), copied.data());
  // `exact`: points whose target is known exactly (a rigid body's map). A group all of whose
  // points are exact is put where its body is: the affine map from its rest points to their
  // targets (a wheel turning in its own slanted plane is affine: a similarity tumbled the oval)
  // as its homography, its offsets cleared (`reset`). Composed onto the previous keyframe as
  // fitted instead, the shape its offsets had drifted into was carried on, and no affine map
  // took it to the target (14 px off by keyframe 3 on a sketched wheel). Tracked points, noisy,
  // give a similarity composed onto the copied homography.
  std::vector<char> reset(static_cast<size_t>(G_), 0);
  auto propose = [&](const PointTracks& tr, const std::vector<char>* exact, std::vector<float>& out) {
    out = copied;
    bool any = false;
    for (int g = 0; g < G_; ++g) {
      if (held_group_[g]) continue;
      std::vector<Vec2> f, t, r;
      std::vector<double> w;
      bool all_exact = exact != nullptr;
      for (size_t j = 0; j < index.size(); ++j)
        if (fplan_.cp_group[index[j]] == g) {
          const size_t i = static_cast<size_t>(index[j]);
          f.push_back(from[j]);
          t.push_back(tr.to[j]);
          w.push_back(tr.weight[j]);
          r.push_back({plan_.rest_cp[2 * i], plan_.rest_cp[2 * i + 1]});
          all_exact = all_exact && (*exact)[j];
        }
      MotionParams th;
      for (int j = 0; j < kMotionParams; ++j) th[j] = copied[g * kMotionParams + j];
      if (all_exact) {
        MotionParams from_rest = identity_params(th[9], th[10]);
        const auto map = least_squares_affine(r.data(), t.data(), r.size());
        if (map && compose_affine(from_rest, *map, {0.5 * W, 0.5 * H}, 0.5 * W)) {
          for (int j = 0; j < kMotionParams; ++j) out[g * kMotionParams + j] = static_cast<float>(from_rest[j]);
          reset[static_cast<size_t>(g)] = 1;
          any = true;
          continue;
        }
      }
      const auto sim = fit_similarity(f, t, w);
      if (!sim) continue;
      compose_similarity(th, *sim, {0.5 * W, 0.5 * H}, 0.5 * W);
      for (int j = 0; j < kMotionParams; ++j) out[g * kMotionParams + j] = static_cast<float>(th[j]);
      any = true;
    }
    return any;
  };
  std::vector<float> tracked, known_params;
  const bool any = propose(tracks, nullptr, tracked);
  std::vector<char> exact;
  std::optional<PointTracks> known = known_tracks(k, index, tracks, exact);
  const bool any_known = known && propose(*known, &exact, known_params);
  if (!any && !any_known && !fplan_.n_nodes) return;
  float loss = frame_loss(k);
  const PointTracks* used = &tracks;
  auto try_params = [&](const std::vector<float>& params) {
    q.enqueueWriteBuffer(params_, CL_TRUE, k * pb * sizeof(float), pb * sizeof(float), params.data());
    const float l = frame_loss(k);
    if (l < loss) {
      loss = l;
      return true;
    }
    return false;
  };
  std::vector<float> best = copied;
  if (any) {
    ++warm_starts_tried;
    if (try_params(tracked)) {
      ++warm_starts_kept;
      best = tracked;
    }
  }
  if (any_known) {
    ++known_starts_tried;
    // The offsets (and field) of the groups put at their bodies' maps, cleared while the known
    // start is tried; put back if it is not kept.
    const size_t no = static_cast<size_t>(plan_.n_cp) * 2, nf = static_cast<size_t>(fplan_.n_nodes) * 2;
    std::vector<float> off(no), field(nf), off_kept, field_kept;
    q.enqueueReadBuffer(offsets_, CL_TRUE, k * no * sizeof(float), no * sizeof(float), off.data());
    if (nf) q.enqueueReadBuffer(field_, CL_TRUE, k * nf * sizeof(float), nf * sizeof(float), field.data());
    off_kept = off;
    field_kept = field;
    for (int i = 0; i < plan_.n_cp; ++i)
      if (fplan_.cp_group[i] >= 0 && reset[static_cast<size_t>(fplan_.cp_group[i])]) off[2 * i] = off[2 * i + 1] = 0;
    for (int b = 0; b < fplan_.n_nodes; ++b) {
      const int first = fplan_.node_cp_first[b];
      if (first < fplan_.node_cp_first[b + 1] && reset[static_cast<size_t>(fplan_.cp_group[fplan_.node_cp[first]])])
        field[2 * b] = field[2 * b + 1] = 0;
    }
    q.enqueueWriteBuffer(offsets_, CL_TRUE, k * no * sizeof(float), no * sizeof(float), off.data());
    if (nf) q.enqueueWriteBuffer(field_, CL_TRUE, k * nf * sizeof(float), nf * sizeof(float), field.data());
    if (try_params(known_params)) {
      ++known_starts_kept;
      best = known_params;
      used = &*known;
    } else {
      q.enqueueWriteBuffer(offsets_, CL_TRUE, k * no * sizeof(float), no * sizeof(float), off_kept.data());
      if (nf) q.enqueueWriteBuffer(field_, CL_TRUE, k * nf * sizeof(float), nf * sizeof(float), field_kept.data());
    }
  }
  q.enqueueWriteBuffer(params_, CL_TRUE, k * pb * sizeof(float), pb * sizeof(float), best.data());
  // Also when no part had tracks enough for a similarity: a small feature's few tracks may
  // still carry it.
  if (fplan_.n_nodes) warm_start_field(k, index, *used, loss);
}

std::optional<PointTracks> Fitter::known_tracks(int k, const std::vector<int>& index, const PointTracks& tracks,
                                                std::vector<char>& exact) const {
  exact.assign(index.size(), 0);
  if (opt_.known_body.empty() || k >= static_cast<int>(target_.source_index.size())) return std::nullopt;
  const int f = target_.source_index[static_cast<size_t>(k)];
  PointTracks out = tracks;
  const Affine inv = size_.view.inverse();
  bool any = false;
  for (size_t j = 0; j < index.size(); ++j) {
    const int p = cp_path_[static_cast<size_t>(index[j])];
    const int b = p >= 0 && p < static_cast<int>(opt_.known_body.size()) ? opt_.known_body[static_cast<size_t>(p)] : -1;
    if (b < 0 || b >= static_cast<int>(opt_.known_maps.size()) || f >= static_cast<int>(opt_.known_maps[b].size())) continue;
    const size_t i = static_cast<size_t>(index[j]);
    const Vec2 rest{plan_.rest_cp[2 * i], plan_.rest_cp[2 * i + 1]};
    out.to[j] = size_.view.apply(opt_.known_maps[static_cast<size_t>(b)][static_cast<size_t>(f)].apply(inv.apply(rest)));
    out.weight[j] = 1;
    out.isotropy[j] = 1;
    exact[j] = 1;
    any = true;
  }
  if (!any) return std::nullopt;
  return out;
}

void Fitter::warm_start_field(int k, const std::vector<int>& index, const PointTracks& tracks, float before) {
  // A track counts when it is consistent both ways and its window sees both directions of
  // the motion (an edge's along-edge motion is unknown; its points simply do not vote).
  constexpr double kMinWeight = 0.5, kMinIsotropy = 0.1;
  // λ: a node triple's bending against one point's misfit (pixels² each); μ: the ridge.
  constexpr double kLambda = 1, kMu = 1e-3;
  auto& q = rt_.queue();
  const size_t n_cp = plan_.n_cp, pb = static_cast<size_t>(G_) * kMotionParams, fb = static_cast<size_t>(fplan_.n_nodes) * 2;
  enqueue_motion(k + 1);
  std::vector<float> cp(n_cp * 2), off(n_cp * 2), par(pb), field(fb);
  q.enqueueReadBuffer(raster_->cp_buffer(), CL_TRUE, k * n_cp * 2 * sizeof(float), cp.size() * sizeof(float), cp.data());
  q.enqueueReadBuffer(total_offsets_, CL_TRUE, k * n_cp * 2 * sizeof(float), off.size() * sizeof(float), off.data());
  q.enqueueReadBuffer(params_, CL_TRUE, k * pb * sizeof(float), pb * sizeof(float), par.data());
  q.enqueueReadBuffer(field_, CL_TRUE, k * fb * sizeof(float), fb * sizeof(float), field.data());
  const Vec2 origin{0.5 * size_.width, 0.5 * size_.height};
  const double scale = 0.5 * size_.width;
  FieldTargets t;
  for (size_t j = 0; j < index.size(); ++j) {
    if (tracks.weight[j] < kMinWeight || tracks.isotropy[j] < kMinIsotropy) continue;
    const int i = index[j];
    if (held_group_[fplan_.cp_group[i]]) continue;
    MotionParams th;
    for (int e = 0; e < kMotionParams; ++e) th[e] = par[fplan_.cp_group[i] * kMotionParams + e];
    // The homography's Jacobian at the point (central differences of the host model): an
    // offset d moves the point by J d.
    const Vec2 x{plan_.rest_cp[2 * i] + off[2 * i], plan_.rest_cp[2 * i + 1] + off[2 * i + 1]};
    const double h = 1e-3;
    const Vec2 jx = (0.5 / h) * (apply_motion(th, x + Vec2{h, 0}, origin, scale) - apply_motion(th, x - Vec2{h, 0}, origin, scale));
    const Vec2 jy = (0.5 / h) * (apply_motion(th, x + Vec2{0, h}, origin, scale) - apply_motion(th, x - Vec2{0, h}, origin, scale));
    const double det = jx.x * jy.y - jy.x * jx.y;
    if (!(std::fabs(det) > 1e-6)) continue;
    const Vec2 r = tracks.to[j] - Vec2{cp[2 * i], cp[2 * i + 1]};
    t.point.push_back(i);
    t.offset.push_back({(jy.y * r.x - jy.x * r.y) / det, (-jx.y * r.x + jx.x * r.y) / det});
    t.weight.push_back(tracks.weight[j]);
  }
  if (t.point.empty()) return;
  const auto inc = fit_field_increment(fplan_, t, kLambda, kMu);
  if (!inc) return;
  ++field_warm_starts_tried;
  std::vector<float> moved = field;
  for (size_t b = 0; b < inc->size(); ++b) {
    moved[2 * b] += static_cast<float>((*inc)[b].x);
    moved[2 * b + 1] += static_cast<float>((*inc)[b].y);
  }
  q.enqueueWriteBuffer(field_, CL_TRUE, k * fb * sizeof(float), fb * sizeof(float), moved.data());
  if (frame_loss(k) < before) ++field_warm_starts_kept;
  else q.enqueueWriteBuffer(field_, CL_TRUE, k * fb * sizeof(float), fb * sizeof(float), field.data());
}

}  // namespace svgm
