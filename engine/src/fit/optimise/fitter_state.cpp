// The fitter's state between fits (see fitter.h): keyframes taken from another fit (the coarse
// fit of the refinement, a fit with fewer keyframes) and the parameters and Adam's state saved
// and put back (checkpoints, rollbacks).
#include "fit/optimise/fitter.h"

#include "fit/optimise/fitter_internal.h"
#include "svgmotion/error.h"

namespace svgm {

using namespace fitter_internal;

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
