// The fitter's host routine (see fitter.h). fit_iteration() is the whole story of one
// iteration, as a list of dispatches on the in-order queue.
#include "fit/optimise/fitter.h"

#include <algorithm>
#include <cmath>

#include "fit/optimise/field_warm_start.h"
#include "fit/optimise/warm_start.h"
#include "geometry/rigid_bodies.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

constexpr int kMotionParams = 12;  // MOTION_PARAMS in kernels/motion.cl
const std::array<float, 4> kWhite{1, 1, 1, 1};

// Per-point containment margins (kernels/regularise.cl): `margin` plus the point's distance to
// the foreground of `sdf` (one frame, [H][W], pixel centres at +0.5), bilinear as the kernel
// reads it, plus the distance beyond the sampled pixel centres. Given the rest points and the rest frame's distances, every point starts inside
// its margin, so containment only resists moving further off the subject than at rest.
std::vector<float> containment_margins(const std::vector<float>& pts, const float* sdf, int width,
                                       int height, double margin) {
  std::vector<float> out(pts.size() / 2, static_cast<float>(margin));
  if (width < 2 || height < 2) return out;
  for (size_t i = 0; i < out.size(); ++i) {
    const double qx = pts[2 * i] - 0.5, qy = pts[2 * i + 1] - 0.5;
    const double x = std::clamp(qx, 0.0, width - 1.0), y = std::clamp(qy, 0.0, height - 1.0);
    const int x0 = std::min(static_cast<int>(x), width - 2), y0 = std::min(static_cast<int>(y), height - 2);
    const double fx = x - x0, fy = y - y0;
    auto S = [&](int xx, int yy) { return static_cast<double>(sdf[static_cast<size_t>(yy) * width + xx]); };
    const double d = (1 - fy) * ((1 - fx) * S(x0, y0) + fx * S(x0 + 1, y0)) +
                     fy * ((1 - fx) * S(x0, y0 + 1) + fx * S(x0 + 1, y0 + 1)) +
                     std::hypot(qx - x, qy - y);
    out[i] = static_cast<float>(margin + std::max(0.0, d));
  }
  return out;
}

}  // namespace

std::vector<float> identity_motion(const FitPlan& f, const RasterPlan& plan, const RenderSize& size) {
  const double ox = 0.5 * size.width, oy = 0.5 * size.height, s = 0.5 * size.width;
  std::vector<float> out(static_cast<size_t>(f.n_groups) * kMotionParams, 0.f);
  for (int g = 0; g < f.n_groups; ++g) {
    double cx = 0, cy = 0;
    const int n = f.group_first[g + 1] - f.group_first[g];
    for (int e = f.group_first[g]; e < f.group_first[g + 1]; ++e) {
      cx += plan.rest_cp[2 * f.group_cps[e]];
      cy += plan.rest_cp[2 * f.group_cps[e] + 1];
    }
    float* th = &out[static_cast<size_t>(g) * kMotionParams];
    th[3] = th[4] = 1.f;  // scale 1; everything else 0
    if (n > 0) {
      th[9] = static_cast<float>((cx / n - ox) / s);
      th[10] = static_cast<float>((cy / n - oy) / s);
    }
  }
  return out;
}

Fitter::Fitter(ClRuntime& rt, const Scene& scene, const TargetFrames& target, const FitOptions& opt)
    : rt_(rt), opt_(opt), target_(target) {
  size_ = render_size(scene, target.width);
  if (size_.height != target.height)
    throw Error("the target is " + std::to_string(target.width) + "x" + std::to_string(target.height) +
                " but the SVG renders at " + std::to_string(size_.width) + "x" +
                std::to_string(size_.height) + " at that width");
  if (opt.iterations < 1) throw Error("iterations must be at least 1");
  K_ = target.keyframes;
  RasterPlanOptions po;
  po.max_chord_px = opt.max_chord_px;
  plan_ = plan_raster(scene, size_.view, size_.width, size_.height, po);
  FitPlanOptions fo;
  fo.smooth_sigma_px = opt_.smooth_sigma_frac * size_.width;
  fo.g1_max_angle_deg = opt_.g1_max_angle_deg;
  fo.field_spacing_px = opt_.field_spacing_frac * size_.width;
  fo.attach_small_px = opt_.attach_small_frac * size_.width;
  fo.attach_invisible_tol = opt_.attach_invisible_tol;
  fo.attach_coincident = opt_.attach_coincident;
  if (opt_.w_cohesion > 0) fo.cohesion_radius_px = opt_.cohesion_radius_frac * size_.width;
  fplan_ = plan_fit(scene, plan_, fo);
  G_ = fplan_.n_groups;
  cp_path_.assign(static_cast<size_t>(plan_.n_cp), -1);
  for (size_t p = 0; p < plan_.path_cp_first.size(); ++p)
    for (int i = 0; i < plan_.path_cp_count[p]; ++i) cp_path_[static_cast<size_t>(plan_.path_cp_first[p] + i)] = static_cast<int>(p);
  held_group_.assign(G_, 0);
  for (int g = 0; g < G_; ++g)
    held_group_[g] = std::find(opt_.held_groups.begin(), opt_.held_groups.end(), fplan_.group_ids[g]) != opt_.held_groups.end();
  for (int b = 0; b < fplan_.n_nodes; ++b) {
    // A node's group is that of its control points (nodes are made per group).
    const int first = fplan_.node_cp_first[b];
    const bool held = first < fplan_.node_cp_first[b + 1] && held_group_[fplan_.cp_group[fplan_.node_cp[first]]];
    if (!held) continue;
    if (!held_nodes_.empty() && held_nodes_.back().first + held_nodes_.back().second == b) ++held_nodes_.back().second;
    else held_nodes_.push_back({b, 1});
  }
  raster_ = std::make_unique<ClRaster>(rt_, plan_, K_, opt_.render_blur_sigma, opt_.chroma_blur_sigma, opt_.chroma_weight);
  raster_->set_targets(target.rgba);
  steps_.assign(K_, 0);

  const size_t K = K_, n_cp = plan_.n_cp;
  auto& ctx = rt_.context();
  auto ro = [&](const auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    return input_buffer(ctx, v.data(), v.size() * sizeof(T));
  };
  auto rw = [&](size_t bytes) {
    cl::Buffer b(ctx, CL_MEM_READ_WRITE, std::max<size_t>(bytes, 16));
    rt_.queue().enqueueFillBuffer(b, 0, 0, std::max<size_t>(bytes, 16));
    return b;
  };
  try {
    cl::Program& prog = rt_.program({"field.cl", "motion.cl", "regularise.cl", "adam.cl"}, kFitterProgramOptions);
    k_motion_ = cl::Kernel(prog, "motion_forward");
    k_motion_back_ = cl::Kernel(prog, "motion_backward");
    k_smooth_ = cl::Kernel(prog, "smoothness");
    k_g1_ = cl::Kernel(prog, "g1_continuity");
    k_contain_ = cl::Kernel(prog, "containment");
    k_sum_ = cl::Kernel(prog, "sum_partials");
    k_adam_p_ = cl::Kernel(prog, "adam");
    k_adam_o_ = cl::Kernel(prog, "adam");
    k_field_ = cl::Kernel(prog, "field_forward");
    k_field_back_ = cl::Kernel(prog, "field_backward");
    k_adam_f_ = cl::Kernel(prog, "adam");
    k_cohesion_ = cl::Kernel(prog, "cohesion");

    std::vector<float> params;
    const auto id = identity_motion(fplan_, plan_, size_);
    for (size_t k = 0; k < K; ++k) params.insert(params.end(), id.begin(), id.end());
    params_ = cl::Buffer(ctx, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, params.size() * sizeof(float),
                         params.data());
    offsets_ = rw(K * n_cp * 2 * sizeof(float));
    total_offsets_ = rw(K * n_cp * 2 * sizeof(float));
    const size_t n_nodes = fplan_.n_nodes;
    field_ = rw(K * n_nodes * 2 * sizeof(float));
    grad_field_ = rw(K * n_nodes * 2 * sizeof(float));
    m_field_ = rw(K * n_nodes * 2 * sizeof(float));
    v_field_ = rw(K * n_nodes * 2 * sizeof(float));
    cp_node_first_ = ro(fplan_.cp_node_first);
    cp_node_ = ro(fplan_.cp_node);
    cp_node_w_ = ro(fplan_.cp_node_w);
    node_cp_first_ = ro(fplan_.node_cp_first);
    node_cp_ = ro(fplan_.node_cp);
    node_cp_w_ = ro(fplan_.node_cp_w);
    coh_first_ = ro(fplan_.coh_first);
    coh_nbr_ = ro(fplan_.coh_nbr);
    coh_len_ = ro(fplan_.coh_len);
    part_coh_ = rw(K * n_cp * sizeof(float));
    rest_ = ro(plan_.rest_cp);
    cp_group_ = ro(fplan_.cp_group);
    cp_offset_ = ro(fplan_.cp_offset);
    group_first_ = ro(fplan_.group_first);
    group_cps_ = ro(fplan_.group_cps);
    nbr_first_ = ro(fplan_.nbr_first);
    nbr_ = ro(fplan_.nbr);
    nbr_w_ = ro(fplan_.nbr_w);
    joints_ = ro(fplan_.joints);
    sdf_ = ro(target.sdf);
    // Keyframe 0 is the rest pose (see FitOptions::pin_rest_keyframe): the rest points'
    // distances to its foreground are how far off the subject each point may be.
    contain_margin_ = ro(containment_margins(plan_.rest_cp, target.sdf.data(), size_.width,
                                             size_.height, opt_.contain_margin_px));
    grad_params_ = rw(params.size() * sizeof(float));
    grad_offsets_ = rw(K * n_cp * 2 * sizeof(float));
    m_params_ = rw(params.size() * sizeof(float));
    v_params_ = rw(params.size() * sizeof(float));
    m_offsets_ = rw(K * n_cp * 2 * sizeof(float));
    v_offsets_ = rw(K * n_cp * 2 * sizeof(float));
    bias_buf_ = rw(K * sizeof(cl_float2));
    const size_t nj = fplan_.n_joints();
    part_smooth_ = rw(K * n_cp * sizeof(float));
    part_contain_ = rw(K * n_cp * sizeof(float));
    part_g1_ = rw(K * std::max<size_t>(nj, 1) * sizeof(float));
    terms_ = rw(4 * sizeof(float));  // smoothness, containment, G1, cohesion
    for (int g : fplan_.cp_group) real_cps_ += g >= 0;

    const cl_float2 origin{{0.5f * size_.width, 0.5f * size_.height}};
    const float scale = 0.5f * size_.width;
    const int ncp = plan_.n_cp, nj_i = static_cast<int>(nj);
    const int nn = fplan_.n_nodes;
    set_args(k_field_, offsets_, field_, cp_node_first_, cp_node_, cp_node_w_, total_offsets_, ncp, nn);
    set_args(k_field_back_, grad_offsets_, node_cp_first_, node_cp_, node_cp_w_, grad_field_, ncp, nn);
    set_args(k_motion_, params_, total_offsets_, rest_, cp_group_, cp_offset_, raster_->cp_buffer(),
             origin, scale, ncp, G_);
    set_args(k_motion_back_, params_, total_offsets_, rest_, cp_offset_, group_first_, group_cps_,
             raster_->cp_gradient_buffer(), grad_params_, grad_offsets_, origin, scale, ncp, G_);
    set_args(k_smooth_, total_offsets_, nbr_first_, nbr_, nbr_w_, grad_offsets_, part_smooth_, 0.f, ncp);
    set_args(k_g1_, raster_->cp_buffer(), joints_, raster_->cp_gradient_buffer(), part_g1_, 0.f,
             ncp, nj_i);
    set_args(k_contain_, raster_->cp_buffer(), cp_group_, sdf_, raster_->cp_gradient_buffer(),
             part_contain_, 0.f, contain_margin_, ncp, size_.width, size_.height);
    set_args(k_cohesion_, raster_->cp_buffer(), coh_first_, coh_nbr_, coh_len_,
             raster_->cp_gradient_buffer(), part_coh_, 0.f, ncp);
    // A pinned rest keyframe keeps its homographies, offsets and field (keyframe 0 of a video
    // that starts mid-motion is fitted like any other).
    const int first_free = opt_.pin_rest_keyframe ? 1 : 0;
    set_args(k_adam_p_, params_, grad_params_, m_params_, v_params_, bias_buf_, G_ * kMotionParams,
             first_free, opt_.lr_homography, opt_.beta1, opt_.beta2, opt_.eps,
             static_cast<int>(K * G_ * kMotionParams));
    set_args(k_adam_o_, offsets_, grad_offsets_, m_offsets_, v_offsets_, bias_buf_, ncp * 2, first_free,
             opt_.lr_offsets, opt_.beta1, opt_.beta2, opt_.eps, static_cast<int>(K * n_cp * 2));
    set_args(k_adam_f_, field_, grad_field_, m_field_, v_field_, bias_buf_, std::max(nn * 2, 1), first_free,
             opt_.lr_field, opt_.beta1, opt_.beta2, opt_.eps, static_cast<int>(K * n_nodes * 2));
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL setup of the fitter failed on ") + rt_.info().name + ": " +
                e.what() + " " + cl_status_name(e.err()));
  }
}

Fitter::~Fitter() = default;

void Fitter::scale_learning_rates(float s) {
  lr_scale_ *= s;
  k_adam_p_.setArg(7, opt_.lr_homography * lr_scale_);  // kernels/adam.cl: argument 7 is lr
  k_adam_o_.setArg(7, opt_.lr_offsets * lr_scale_);
  k_adam_f_.setArg(7, opt_.lr_field * lr_scale_);
}

void Fitter::adopt_coarse(Fitter& coarse, double scale) {
  if (coarse.K_ != K_) throw Error("internal: keyframes taken from a fit of another shape");
  std::vector<int> from(static_cast<size_t>(K_));
  for (int k = 0; k < K_; ++k) from[static_cast<size_t>(k)] = k;
  adopt_coarse_from(coarse, scale, from);
}

void Fitter::adopt_coarse_from(Fitter& coarse, double scale, const std::vector<int>& from) {
  copy_keyframes(coarse, scale, from);
  last_activation_ = 0;
  plateau_ref_.clear();
  newest_ref_ = -1;
  converged_ = false;
  // Fresh Adam moments everywhere (the field itself is zero: take_keyframes folded it away).
  auto& q = rt_.queue();
  const size_t np = static_cast<size_t>(K_) * G_ * kMotionParams, no = static_cast<size_t>(K_) * plan_.n_cp * 2;
  for (cl::Buffer* b : {&m_params_, &v_params_}) q.enqueueFillBuffer(*b, 0.f, 0, np * sizeof(float));
  for (cl::Buffer* b : {&m_offsets_, &v_offsets_}) q.enqueueFillBuffer(*b, 0.f, 0, no * sizeof(float));
  const size_t nf = static_cast<size_t>(K_) * fplan_.n_nodes * 2;
  if (nf)
    for (cl::Buffer* b : {&m_field_, &v_field_}) q.enqueueFillBuffer(*b, 0.f, 0, nf * sizeof(float));
  q.finish();
  iteration_ = 0;
  active_ = K_;
  steps_.assign(K_, 0);
}

int Fitter::activation_iteration(int k) const {
  if (k <= 0 || K_ <= 1) return 0;
  const int interval = std::max(1, static_cast<int>(opt_.activation_share * opt_.iterations / (K_ - 1)));
  // A pinned rest keyframe has nothing to fit: keyframe 1 starts at once instead of after an
  // interval in which no parameter moves (the paper's schedule spent its first 100 of 2000
  // iterations there); the interval goes to the joint refinement.
  return (opt_.pin_rest_keyframe ? k - 1 : k) * interval;
}

namespace {

// b^t in float by repeated squaring, the operations kernels/adam.cl used to do per element
// (so fits keep their bits): at most 2 log2(t) roundings, ~1e-6 relative for t <= a few
// thousand, which the bias corrections do not notice.
float float_power(float b, int t) {
  float r = 1.0f;
  while (t > 0) {
    if (t & 1) r *= b;
    b *= b;
    t >>= 1;
  }
  return r;
}

}  // namespace

void Fitter::upload_steps() {
  bias_.resize(steps_.size());
  for (size_t k = 0; k < steps_.size(); ++k) {
    const int t = steps_[k];
    bias_[k] = t > 0 ? cl_float2{{1.0f - float_power(opt_.beta1, t), 1.0f - float_power(opt_.beta2, t)}}
                     : cl_float2{{0, 0}};
  }
  rt_.queue().enqueueWriteBuffer(bias_buf_, CL_FALSE, 0, bias_.size() * sizeof(cl_float2), bias_.data());
}

void Fitter::activate_keyframe(int k) {
  // Start from the previous keyframe: its homographies and offsets, fresh Adam moments.
  auto& q = rt_.queue();
  const size_t pb = static_cast<size_t>(G_) * kMotionParams * sizeof(float);
  const size_t ob = static_cast<size_t>(plan_.n_cp) * 2 * sizeof(float);
  q.enqueueCopyBuffer(params_, params_, (k - 1) * pb, k * pb, pb);
  q.enqueueCopyBuffer(offsets_, offsets_, (k - 1) * ob, k * ob, ob);
  q.enqueueFillBuffer(m_params_, 0.f, k * pb, pb);
  q.enqueueFillBuffer(v_params_, 0.f, k * pb, pb);
  q.enqueueFillBuffer(m_offsets_, 0.f, k * ob, ob);
  q.enqueueFillBuffer(v_offsets_, 0.f, k * ob, ob);
  if (fplan_.n_nodes) {
    const size_t fb = static_cast<size_t>(fplan_.n_nodes) * 2 * sizeof(float);
    q.enqueueCopyBuffer(field_, field_, (k - 1) * fb, k * fb, fb);
    q.enqueueFillBuffer(m_field_, 0.f, k * fb, fb);
    q.enqueueFillBuffer(v_field_, 0.f, k * fb, fb);
  }
  steps_[k] = 0;
  if (opt_.track) warm_start(k, k - 1);
}

void Fitter::enqueue_motion(int frames) {
  auto& q = rt_.queue();
  const cl::NDRange range(round_up(plan_.n_cp, 64), frames);
  enqueue_stable(q, k_field_, range);
  enqueue_stable(q, k_motion_, range);
}

void Fitter::zero_held_gradients() {
  auto& q = rt_.queue();
  const float zero = 0;
  for (int k = 0; k < K_; ++k) {
    for (int g = 0; g < G_; ++g)
      if (held_group_[g])
        q.enqueueFillBuffer(grad_params_, zero, (static_cast<size_t>(k) * G_ + g) * kMotionParams * sizeof(float),
                            kMotionParams * sizeof(float));
    for (const auto& [first, count] : held_nodes_)
      q.enqueueFillBuffer(grad_field_, zero, (static_cast<size_t>(k) * fplan_.n_nodes + first) * 2 * sizeof(float),
                          static_cast<size_t>(count) * 2 * sizeof(float));
  }
}

float Fitter::frame_loss(int k) {
  enqueue_motion(k + 1);
  raster_->set_active_frames(k + 1);
  raster_->enqueue_loss_and_gradient(opt_.w_image, kWhite);
  return raster_->read_frame_losses()[k];
}

void Fitter::warm_start(int k, int src) {
  auto& q = rt_.queue();
  const int W = size_.width, H = size_.height;
  // The source keyframe as fitted so far (the previous one, or k itself as copied): its
  // render and its control points.
  enqueue_motion(src + 1);
  raster_->set_active_frames(src + 1);
  raster_->forward(ClRaster::Output::Float, kWhite);
  const auto img = raster_->read_image_frame(src);
  std::vector<float> cp(static_cast<size_t>(plan_.n_cp) * 2);
  q.enqueueReadBuffer(raster_->cp_buffer(), CL_TRUE, static_cast<size_t>(src) * plan_.n_cp * 2 * sizeof(float),
                      cp.size() * sizeof(float), cp.data());
  std::vector<uint8_t> prev(static_cast<size_t>(W) * H), next(prev.size());
  auto grey = [](float r, float g, float b) {
    return static_cast<uint8_t>(std::clamp(255.f * (0.299f * r + 0.587f * g + 0.114f * b) + 0.5f, 0.f, 255.f));
  };
  for (size_t p = 0; p < prev.size(); ++p) {
    const float* c = &img[p * 4];
    prev[p] = grey(c[0] + 1 - c[3], c[1] + 1 - c[3], c[2] + 1 - c[3]);
    const float* t = &target_.rgba[((static_cast<size_t>(k) * H * W) + p) * 4];
    next[p] = grey(t[0], t[1], t[2]);
  }
  std::vector<Vec2> from;
  std::vector<int> index;
  for (int i = 0; i < plan_.n_cp; ++i)
    if (fplan_.cp_group[i] >= 0 && fplan_.cp_offset[i] == i) {
      from.push_back({cp[2 * i], cp[2 * i + 1]});
      index.push_back(i);
    }
  PointTracks tracks;
  if (src == k - 1 && k < static_cast<int>(flows_.size()) && flows_[k].grid > 0) {
    // The tracker stage's flow between the target keyframes, at the fitted points.
    tracks.to = from;
    tracks.weight.assign(from.size(), 0.0);
    for (size_t j = 0; j < from.size(); ++j) {
      double dx, dy, w;
      flows_[k].sample(from[j].x, from[j].y, W, H, &dx, &dy, &w);
      tracks.to[j] = from[j] + Vec2{dx, dy};
      tracks.weight[j] = w;
    }
    tracks.isotropy = window_isotropy(prev, W, H, from, 7);  // as track_points' 15 px window
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

LossTerms Fitter::step() {
  while (active_ < K_ && activation_due()) {
    activate_keyframe(active_);
    ++active_;
    last_activation_ = iteration_;
    plateau_ref_.clear();
    newest_ref_ = -1;
  }
  // Keyframe 0 fitted freely (a video that starts mid-motion): carried from the rest pose
  // toward its frame before its first step, as every later keyframe is from the one before.
  if (iteration_ == 0 && active_ == 1 && !opt_.pin_rest_keyframe && opt_.track && !started_) warm_start(0, 0);
  started_ = true;
  const LossTerms t = fit_iteration();
  ++iteration_;
  check_plateau();
  return t;
}

namespace {

double mean_of(const std::vector<float>& v) {
  double m = 0;
  for (float x : v) m += x;
  return v.empty() ? 0 : m / static_cast<double>(v.size());
}

// Whether a loss fell from `before` to `after` by more than `tol` of `before` or `floor`,
// whichever is larger (the adaptive activation's and the plateau's test: a loss matched almost
// exactly wobbles by more than the tolerance of itself, and the floor keeps that from counting).
bool fell(double before, double after, double tol, double floor) {
  return before - after > tol * std::max(before, floor);
}

}  // namespace

bool Fitter::activation_due() {
  // The paper's schedule: keyframe 1 (after a pinned rest keyframe) at once, then one every
  // interval; never later than that after the previous activation.
  const int w = opt_.activation_window;
  if (w <= 0) return iteration_ >= activation_iteration(active_);
  const int since = iteration_ - last_activation_;
  if (since >= activation_iteration(active_) - activation_iteration(active_ - 1)) return true;
  if (since == 0 || since % w != 0) return false;
  // The newest keyframe's loss after the last iteration (read_frame_losses: the active ones);
  // its fall is measured against its loss or the active keyframes' mean, whichever is larger
  // (a keyframe matched almost exactly wobbles by more than the tolerance of its tiny loss).
  const std::vector<float> losses = raster_->read_frame_losses();
  const float now = losses.back();
  const bool settled = newest_ref_ >= 0 && !fell(newest_ref_, now, opt_.activation_tol, mean_of(losses));
  newest_ref_ = now;
  return settled;
}

void Fitter::check_plateau() {
  const int w = opt_.plateau_window;
  if (w <= 0 || active_ < K_ || (iteration_ - last_activation_) % w != 0) return;
  // The losses of the iteration just done. The fit has converged when the keyframes' mean loss
  // fell by less than plateau_tol over the window, and no keyframe's by more than
  // plateau_tol_keyframe of its own loss or the mean, whichever is larger: a keyframe still
  // settling (the last activated: tens of percent per window) keeps the fit going however flat
  // the mean is, while Adam's wobble (single keyframes up and down by 1-2 % per window while
  // the mean moves 0.1 %: kite) does not.
  const std::vector<float> now = raster_->read_frame_losses();
  if (!plateau_ref_.empty()) {
    const double ref_mean = mean_of(plateau_ref_);
    bool flat = !fell(ref_mean, mean_of(now), opt_.plateau_tol, 0);
    for (size_t k = 0; k < now.size() && flat; ++k)
      flat = !fell(plateau_ref_[k], now[k], opt_.plateau_tol_keyframe, ref_mean);
    converged_ = flat;
  }
  plateau_ref_ = now;
}

LossTerms Fitter::fit_iteration() {
  const size_t Ka = static_cast<size_t>(active_), n_cp = plan_.n_cp;
  const size_t nj = fplan_.n_joints();
  auto& q = rt_.queue();
  for (int k = 0; k < active_; ++k) ++steps_[k];
  upload_steps();
  raster_->set_active_frames(active_);
  k_smooth_.setArg(6, fplan_.n_pairs ? opt_.w_smooth / (Ka * fplan_.n_pairs) : 0.f);
  k_g1_.setArg(4, nj ? opt_.w_g1 / (Ka * nj) : 0.f);
  k_contain_.setArg(5, real_cps_ ? opt_.w_contain / (Ka * real_cps_) : 0.f);
  const int ncoh = fplan_.n_coh_pairs;
  k_cohesion_.setArg(6, ncoh ? opt_.w_cohesion / (Ka * ncoh) : 0.f);
  try {
    // 1. Motion: field + free offsets -> offsets; homographies and offsets -> control points
    //    of the active keyframes.
    enqueue_motion(active_);
    // 2. Render, blurred MSE against the targets, exact gradient to the control points.
    raster_->enqueue_loss_and_gradient(opt_.w_image, kWhite);
    // 3. G1 continuity, containment and cohesion add to the control-point gradient.
    if (nj) enqueue_stable(q, k_g1_, cl::NDRange(round_up(nj, 64), Ka));
    enqueue_stable(q, k_contain_, cl::NDRange(round_up(n_cp, 64), Ka));
    if (ncoh) enqueue_stable(q, k_cohesion_, cl::NDRange(round_up(n_cp, 64), Ka));
    // 4. Back through the motion model to homographies and offsets.
    enqueue_stable(q, k_motion_back_, cl::NDRange(round_up(G_, 8), Ka));
    // 5. Smoothness adds to the offset gradient.
    enqueue_stable(q, k_smooth_, cl::NDRange(round_up(n_cp, 64), Ka));
    // 6. Back through the fields to their coefficients (the free offsets' gradient is the
    //    offsets' gradient itself).
    const size_t nn = fplan_.n_nodes;
    if (nn) enqueue_stable(q, k_field_back_, cl::NDRange(round_up(nn, 64), Ka));
    // 7. Adam on every active keyframe (a pinned rest keyframe stays the identity; so do the
    //    held groups' in every keyframe).
    zero_held_gradients();
    enqueue_stable(q, k_adam_p_,
                           cl::NDRange(round_up(static_cast<size_t>(K_) * G_ * kMotionParams, 64)));
    if (opt_.lr_offsets != 0)
      enqueue_stable(q, k_adam_o_, cl::NDRange(round_up(K_ * n_cp * 2, 64)));
    if (nn) enqueue_stable(q, k_adam_f_, cl::NDRange(round_up(K_ * nn * 2, 64)));
    // 8. The regularisers' values, summed in order.
    set_args(k_sum_, part_smooth_, terms_, 0, static_cast<int>(Ka * n_cp));
    enqueue_stable(q, k_sum_, cl::NDRange(1));
    set_args(k_sum_, part_contain_, terms_, 1, static_cast<int>(Ka * n_cp));
    enqueue_stable(q, k_sum_, cl::NDRange(1));
    set_args(k_sum_, part_g1_, terms_, 2, static_cast<int>(Ka * nj));
    enqueue_stable(q, k_sum_, cl::NDRange(1));
    if (ncoh) {
      set_args(k_sum_, part_coh_, terms_, 3, static_cast<int>(Ka * n_cp));
      enqueue_stable(q, k_sum_, cl::NDRange(1));
    }
    LossTerms t;
    float terms[4] = {0, 0, 0, 0};
    q.enqueueReadBuffer(terms_, CL_FALSE, 0, (ncoh ? 4 : 3) * sizeof(float), terms);
    t.image = raster_->read_loss();  // blocks: the iteration is done
    t.smooth = terms[0];
    t.contain = terms[1];
    t.g1 = terms[2];
    t.cohesion = terms[3];
    return t;
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL fit iteration failed on ") + rt_.info().name + ": " + e.what() +
                " " + cl_status_name(e.err()));
  }
}

std::vector<double> Fitter::keyframe_points_canvas() {
  auto& q = rt_.queue();
  enqueue_motion(K_);
  std::vector<float> cp(static_cast<size_t>(K_) * plan_.n_cp * 2);
  q.enqueueReadBuffer(raster_->cp_buffer(), CL_TRUE, 0, cp.size() * sizeof(float), cp.data());
  const Affine inv = size_.view.inverse();
  std::vector<double> out(cp.size());
  for (size_t i = 0; i < cp.size(); i += 2) {
    const Vec2 c = inv.apply({cp[i], cp[i + 1]});
    out[i] = c.x;
    out[i + 1] = c.y;
  }
  return out;
}

std::vector<float> Fitter::render_keyframes() {
  enqueue_motion(active_);
  raster_->set_active_frames(active_);
  raster_->forward(ClRaster::Output::Float, kWhite);
  auto img = raster_->read_image();
  img.resize(static_cast<size_t>(active_) * size_.width * size_.height * 4);
  return img;
}

std::vector<float> Fitter::keyframe_losses() { return raster_->read_frame_losses(); }

void Fitter::release_loss_memory() { raster_->release_loss_buffers(); }

std::vector<float> Fitter::evaluate_keyframe_losses() {
  enqueue_motion(K_);
  raster_->set_active_frames(K_);
  raster_->enqueue_loss_and_gradient(opt_.w_image, kWhite);
  return raster_->read_frame_losses();
}

void Fitter::take_keyframes(Fitter& other, double scale, const std::vector<char>& which) {
  if (other.K_ != K_ || which.size() != static_cast<size_t>(K_))
    throw Error("internal: keyframes taken from a fit of another shape");
  std::vector<int> from(static_cast<size_t>(K_), -1);
  for (int k = 0; k < K_; ++k)
    if (which[static_cast<size_t>(k)]) from[static_cast<size_t>(k)] = k;
  copy_keyframes(other, scale, from);
}

void Fitter::adopt_keyframes(Fitter& other, const std::vector<int>& from, const std::vector<char>& fresh) {
  if (from.size() != static_cast<size_t>(K_) || fresh.size() != from.size())
    throw Error("internal: keyframes adopted from a fit of another shape");
  // As the refinement adopts the coarse fit (every keyframe active, fresh Adam moments), at the
  // same width; then each new keyframe is carried from its source's pose toward its own target.
  adopt_coarse_from(other, 1, from);
  if (!opt_.track) return;
  for (int k = 0; k < K_; ++k)
    if (fresh[static_cast<size_t>(k)]) warm_start(k, k);
}

void Fitter::copy_keyframes(Fitter& other, double scale, const std::vector<int>& from) {
  if (other.G_ != G_ || other.plan_.n_cp != plan_.n_cp || from.size() != static_cast<size_t>(K_))
    throw Error("internal: keyframes taken from a fit of another shape");
  auto& oq = other.rt_.queue();
  const size_t pk = static_cast<size_t>(G_) * kMotionParams, ok = static_cast<size_t>(plan_.n_cp) * 2;
  const size_t OK = static_cast<size_t>(other.K_);
  std::vector<float> oparams(OK * pk), ooffsets(OK * ok);
  other.enqueue_motion(other.K_);  // its total offsets (free + field) of every keyframe
  oq.enqueueReadBuffer(other.params_, CL_TRUE, 0, oparams.size() * sizeof(float), oparams.data());
  oq.enqueueReadBuffer(other.total_offsets_, CL_TRUE, 0, ooffsets.size() * sizeof(float), ooffsets.data());
  auto& q = rt_.queue();
  const size_t fk = static_cast<size_t>(fplan_.n_nodes) * 2;
  for (int k = 0; k < K_; ++k) {
    const int j = from[static_cast<size_t>(k)];
    if (j < 0) continue;
    if (j >= other.K_) throw Error("internal: a keyframe taken from one the other fit does not have");
    std::vector<float> off(ooffsets.begin() + j * ok, ooffsets.begin() + (j + 1) * ok);
    for (float& o : off) o = static_cast<float>(o * scale);
    q.enqueueWriteBuffer(params_, CL_TRUE, k * pk * sizeof(float), pk * sizeof(float), oparams.data() + j * pk);
    q.enqueueWriteBuffer(offsets_, CL_TRUE, k * ok * sizeof(float), ok * sizeof(float), off.data());
    if (fk) q.enqueueFillBuffer(field_, 0.f, k * fk * sizeof(float), fk * sizeof(float));
  }
  q.finish();
}

FitState Fitter::state() {
  FitState s;
  s.iteration = iteration_;
  s.active = active_;
  s.steps = steps_;
  s.schedule = true;
  s.converged = converged_;
  s.last_activation = last_activation_;
  s.newest_ref = newest_ref_;
  s.lr_scale = lr_scale_;
  s.plateau_ref = plateau_ref_;
  auto rd = [&](cl::Buffer& b, std::vector<float>& v, size_t n) {
    v.resize(n);
    if (n) rt_.queue().enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(float), v.data());
  };
  const size_t np = static_cast<size_t>(K_) * G_ * kMotionParams, no = static_cast<size_t>(K_) * plan_.n_cp * 2;
  rd(params_, s.params, np);
  rd(m_params_, s.m_params, np);
  rd(v_params_, s.v_params, np);
  rd(offsets_, s.offsets, no);
  rd(m_offsets_, s.m_offsets, no);
  rd(v_offsets_, s.v_offsets, no);
  const size_t nf = static_cast<size_t>(K_) * fplan_.n_nodes * 2;
  rd(field_, s.field, nf);
  rd(m_field_, s.m_field, nf);
  rd(v_field_, s.v_field, nf);
  return s;
}

void Fitter::restore(const FitState& s) {
  const size_t np = static_cast<size_t>(K_) * G_ * kMotionParams, no = static_cast<size_t>(K_) * plan_.n_cp * 2;
  const size_t nf = static_cast<size_t>(K_) * fplan_.n_nodes * 2;
  if (s.params.size() != np || s.offsets.size() != no || s.steps.size() != static_cast<size_t>(K_) ||
      s.m_params.size() != np || s.v_params.size() != np || s.m_offsets.size() != no ||
      s.v_offsets.size() != no || s.active < 1 || s.active > K_ ||
      s.field.size() != nf || s.m_field.size() != nf || s.v_field.size() != nf)
    throw Error("the checkpoint does not match this SVG and keyframe count");
  auto wr = [&](cl::Buffer& b, const std::vector<float>& v) {
    rt_.queue().enqueueWriteBuffer(b, CL_TRUE, 0, v.size() * sizeof(float), v.data());
  };
  wr(params_, s.params);
  wr(m_params_, s.m_params);
  wr(v_params_, s.v_params);
  wr(offsets_, s.offsets);
  wr(m_offsets_, s.m_offsets);
  wr(v_offsets_, s.v_offsets);
  if (nf) {
    wr(field_, s.field);
    wr(m_field_, s.m_field);
    wr(v_field_, s.v_field);
  }
  iteration_ = s.iteration;
  active_ = s.active;
  // The plateau test starts afresh: a window from here on.
  last_activation_ = iteration_;
  plateau_ref_.clear();
  newest_ref_ = -1;
  converged_ = false;
  steps_ = s.steps;
}

void Fitter::resume(const FitState& s) {
  restore(s);
  if (!s.schedule) return;
  converged_ = s.converged && opt_.plateau_window > 0;
  last_activation_ = s.last_activation;
  newest_ref_ = s.newest_ref;
  plateau_ref_ = s.plateau_ref;
  if (s.lr_scale != lr_scale_) scale_learning_rates(s.lr_scale / lr_scale_);
}

}  // namespace svgm
