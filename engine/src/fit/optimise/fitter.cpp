// The fitter's host routine (see fitter.h): its setup and fit_iteration(), the whole story of one
// iteration as a list of dispatches on the in-order queue. The schedule, the warm starts and the
// state kept between fits live beside it (fitter_schedule.cpp, fitter_warm_start.cpp,
// fitter_state.cpp).
#include "fit/optimise/fitter.h"

#include <algorithm>
#include <cmath>

#include "fit/optimise/fitter_internal.h"
#include "svgmotion/error.h"

namespace svgm {

using namespace fitter_internal;

namespace {

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
  // A target its holder keeps packed (fit_run.h) gives the loss no frames until read_targets_from.
  if (target.rgba.empty()) raster_->set_target_frames([](int, float*) { throw Error("internal: packed targets unread"); });
  else raster_->set_targets(target.rgba);
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
    cl::Program& prog = rt_.program({"field.cl", "motion.cl", "regularise.cl", "adam.cl"}, kFitterProgramOptions, "fitter");
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
    // Groups of 8 whatever the group count, so that its compiled work-group function is the same
    // for every drawing (as the raster's stroke kernels; opencl/compile_child.h).
    q.enqueueNDRangeKernel(k_motion_back_, cl::NullRange, cl::NDRange(round_up(G_, 8), Ka), cl::NDRange(8, 1));
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
  return raster_->render_frames(0, active_, kWhite);
}

std::vector<float> Fitter::render_keyframe(int k) {
  if (k < 0 || k >= K_) throw Error("internal: render_keyframe " + std::to_string(k) + " of " + std::to_string(K_));
  enqueue_motion(k + 1);
  return raster_->render_frames(k, 1, kWhite);
}

std::vector<float> Fitter::keyframe_losses() { return raster_->read_frame_losses(); }

void Fitter::release_loss_memory() { raster_->release_loss_buffers(); }

void Fitter::prepare_loss_memory() { raster_->prepare_loss(kWhite); }

void Fitter::read_targets_from(std::function<void(int k, float* rgba)> frame) {
  raster_->set_target_frames(std::move(frame));
}

void Fitter::read_targets_whole() { raster_->set_targets(target_.rgba); }

std::vector<float> Fitter::evaluate_keyframe_losses() {
  enqueue_motion(K_);
  raster_->set_active_frames(K_);
  raster_->enqueue_loss_and_gradient(opt_.w_image, kWhite);
  return raster_->read_frame_losses();
}

}  // namespace svgm
