// The fitter: a static SVG plus target keyframes in, keyframed control points out.
//
// Parameters per keyframe: an 8-DOF homography per group (kernels/motion.cl, 11 numbers with
// its learned centre), the coefficients of each group's smooth displacement field
// (kernels/field.cl) and a free residual offset per control point. One iteration
// (fit_iteration) runs on the device: field -> motion -> control points -> raster + blurred
// MSE + backward -> G1, containment and cohesion gradients -> motion backward -> smoothness ->
// field backward -> Adam. Keyframes are activated one at a time
// (copy of the previous one, optionally improved by optical-flow tracking), then refined
// jointly; the schedule scales with the iteration budget.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fit/plan/fit_plan.h"
#include "fit/optimise/flow_tracks.h"
#include "fit/optimise/warm_start.h"
#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "svgmotion/render_size.h"
#include "svgmotion/scene.h"
#include "svgmotion/target_video.h"

namespace svgm {

struct FitOptions {
  int iterations = 2000;           // paper: 2000
  float w_image = 1000;            // paper, appendix: blurred MSE weight
  // Offset smoothness weight (paper: 0.5). 0.2: with the displacement field the offsets are
  // smooth by construction and the paper's weight mostly resisted real bends; without it at
  // all, thin parts wander with the codec's noise. Worst keyframe, 0.5 -> 0.2 -> 0: octopus
  // non-rigid at 1024 px 39.7 -> 41.4 -> 41.9 dB, parrot 36.7 -> 37.9 -> 39.1; man_fencing
  // smooth warp at 256 px 44.8 -> 44.4 -> 40.2, man_dance 40.8 -> 40.3 -> 38.5.
  float w_smooth = 0.2f;
  float w_g1 = 10;                 // paper: G1 continuity weight
  float w_contain = 1;             // paper: containment weight
  float lr_homography = 1e-3f;     // paper: Adam learning rate of homography parameters
  // Adam learning rate of the free per-point offsets (pixels); the paper's is 0.1. 0 by
  // default: with the displacement field below, free points are what lets thin parts tear at
  // display size (use_free_offsets() restores the paper's deformation).
  float lr_offsets = 0;
  float beta1 = 0.9f, beta2 = 0.9f, eps = 1e-6f;  // paper: Adam settings
  double smooth_sigma_frac = 0.01; // σ of smoothness weights, fraction of the canvas width
  double g1_max_angle_deg = 10;    // joints smoother than this at rest keep G1 continuity
  // Containment margin beyond each point's own distance to the subject at rest (a handle of a
  // convex curve lies outside the shape it draws; kernels/regularise.cl).
  double contain_margin_px = 1;
  // Share of the iterations spent activating keyframes (paper: one about every 100 of 2000,
  // i.e. 14 activations over 1400 iterations); the rest is joint refinement.
  double activation_share = 0.7;
  bool track = true;               // optical-flow warm start of each activated keyframe
  // Adaptive activation: the next keyframe is activated as soon as the newest one has settled,
  // its image loss falling by less than `activation_tol` (relative) over `activation_window`
  // iterations, and at the latest after the paper's interval (activation_share). 0 window:
  // the paper's fixed schedule. A warm-started keyframe usually settles within a window or
  // two, and the joint refinement goes on over every active keyframe anyway; the activation
  // phase is most of a fit's cost (15 keyframes one per 100 iterations: 10500 of the 13500
  // keyframe-iterations of a fit that converges 200 iterations after the last activation).
  // Window 25 -> 20 on emoji_u1f69e (a train, 69 paths): 30.9 -> 25.8 s, 40.36 -> 40.38 dB;
  // non-rigid kite, woman_wave, man_skiing, parrot within 0.15 dB at 1024 px. Tolerance 0.02 ->
  // 0.04 (wall s on a quiet machine, fitcheck dB at 256 px): emoji_u1f682 33.3 -> 27.9 s,
  // 37.12 -> 37.27; emoji_u1f69e 34.0 -> 27.4 s, 40.26 -> 40.27; emoji_u1f3de 34.3 -> 26.7 s,
  // 38.14 -> 38.13; emoji_u1f303 23.9 -> 19.9 s, 37.91 -> 37.92; non-rigid worst keyframe at
  // 1024 px: kite 44.96 -> 45.06, man_skiing 44.58 -> 44.70, woman_wave 41.54 -> 41.51,
  // parrot and octopus unchanged. 0.06 gains nothing more (emoji_u1f682 27.9 s). Window 20 ->
  // 10 (with the plateau window 100 -> 50 below; iterations to convergence, fitcheck dB at 256
  // px): emoji_u1f682 1240 -> 960, 37.27 -> 37.28; emoji_u1f69e 1160 -> 800, 40.27 -> 40.27;
  // emoji_u1f9d1_200d_1f4bb 1040 -> 630, 35.48 -> 35.52; u1F371-bentobox 1120 -> 970, 37.58 ->
  // 37.59; CPU seconds 25-30% fewer. Non-rigid worst keyframes at 1024 px within 0.25 dB: kite
  // 45.06 -> 45.02, woman_wave 41.51 -> 41.53, parrot 42.72 -> 42.83, man_skiing 44.70 ->
  // 44.47, octopus 46.29 -> 46.50.
  int activation_window = 10;
  float activation_tol = 0.04f;
  // Convergence: once every keyframe is active, the fit stops before `iterations` when over the
  // last `plateau_window` iterations the keyframes' mean image loss fell by less than
  // `plateau_tol` and none fell by more than `plateau_tol_keyframe` (relative; Fitter::
  // check_plateau). 0 window: every iteration runs. The paper's 2000 iterations end with 700
  // of joint refinement over all 15 keyframes, the costliest stretch, in which the loss no
  // longer moves: emoji_u1f303 0.72957 -> 0.72928 over iterations 1400-2000, kite 0.00742 ->
  // 0.00738.
  // Window 100 -> 50 at the same rates (tolerances halved): the end is found within 50
  // iterations of 15 keyframes instead of 100 (emoji_u1f682 1240 -> 1140 alone, same dB).
  int plateau_window = 50;
  float plateau_tol = 0.0025f;
  float plateau_tol_keyframe = 0.015f;
  // Knot spacing of each group's displacement field (kernels/field.cl), as a fraction of the
  // canvas width; 0 turns the field off (offsets are then only the free per-point ones).
  // 1/32 (8 px at 256): a tentacle's bend is followed within a knot, while anything thinner
  // than a knot (a ribbon, a finger's gap) still moves as one. Measured on non-rigid targets at
  // 1024 px, 1/16 -> 1/32: octopus worst keyframe 34.15 -> 35.94 dB, boundary F 0.975 -> 0.985;
  // parrot 35.63 -> 36.66 dB; bug 40.68 -> 40.68 (1/48: octopus 36.34, little more).
  double field_spacing_frac = 1.0 / 32;
  float lr_field = 1e-1f;          // Adam learning rate of the field coefficients (pixels)
  // Every cubic is drawn with at least one chord per this many pixels of its control polygon
  // (RasterPlanOptions::max_chord_px). Wang's bound, taken at rest, gives a segment straight at
  // rest one chord, which depends on its end points only: the loss never saw its handles, and
  // the exported curve bulged wherever they drifted (kite: a straight edge bent into an S came
  // out with a kink). Non-rigid 512-px targets judged at 1024 px, worst keyframe, Wang's bound
  // alone -> 4 px: kite 35.68 -> 45.11 dB, man_skiing 34.03 -> 44.64, woman_wave 33.22 ->
  // 41.46; octopus, parrot, bug, snail within +-0.5. 0: Wang's bound alone.
  double max_chord_px = 4;
  // Ungrouped paths smaller than this fraction of the canvas width (both sides of the rest
  // bounding box) move with the path they sit on (FitPlanOptions::attach_small_px); 0: off.
  double attach_small_frac = 0.025;
  // Paths alone in their group that vanish on white (within this of white per channel: the
  // default white threshold's 1 - 0.97) move with the visible path they sit on
  // (FitPlanOptions::attach_invisible_tol); negative: off.
  double attach_invisible_tol = 0.03;
  // Paths alone in their group with an earlier path's outline move with it
  // (FitPlanOptions::attach_coincident).
  bool attach_coincident = true;
  float w_cohesion = 0;            // weight of cohesion (kernels/regularise.cl); 0: off
  double cohesion_radius_frac = 0.015;  // cohesion pairs: rest distance below this x width
  // Keyframe 0 is the rest pose: an image-to-video model starts from the input image, so the
  // first frame shows the drawing as it is. Its homographies are always the identity; with this
  // its offsets and field stay zero too, instead of chasing the codec's noise in that frame
  // (parrot, non-rigid target, H.264 at 37 dB: keyframe 0 drifted to 40.4 dB at 1024 px
  // where the SVG itself scores 59.5).
  bool pin_rest_keyframe = true;
  // The σ of the Gaussian the loss blurs the render with (the target's is the paper's 1): set
  // from the rest pose by blur matching (fit/target/blur_match.h) when the video is softer.
  double render_blur_sigma = 1;
  // The σ of the render's chroma blur in YCbCr when blur matching found the video's chroma
  // softer than its luma (raster/loss_taps.h, render_blur); 0: render_blur_sigma, every
  // channel alike.
  double chroma_blur_sigma = 0;
  // How much a residual of chroma alone counts against one of luma (kernels/loss.cl's
  // loss_metric); 1: the plain squared error.
  double chroma_weight = 1;

  // The paper's deformation: free per-point offsets (lr 0.1) with its smoothness weight, no
  // displacement field.
  void use_free_offsets() {
    lr_offsets = 1e-1f;
    w_smooth = 0.5f;
    field_spacing_frac = 0;
  }

  // Learning rate (pixels of the finer width) of the free per-point offsets in the
  // coarse-to-fine refinement (refined_at), when the coarse fit has none: at the finer width
  // the loss sees what is one or two pixels wide at the coarse one, so each point may follow
  // it. Measured on 512-px non-rigid targets judged at 1024 px, worst keyframe with the field
  // alone -> with these offsets: parrot 39.93 -> 41.71 dB, octopus and bug unchanged.
  float lr_refine_offsets = 0.05f;

  // The same fit `scale` times wider (the refinement stage). The regularisers that sum squared
  // pixel distances (smoothness of the offsets, containment, cohesion) are divided by scale²
  // and the containment margin multiplied by scale, so they weigh the same geometry as at the
  // coarse width, not four times as much at twice the width: the image loss is a mean over
  // pixels and does not grow with the width. (Unscaled, parrot's refinement at 512 px held
  // its worst keyframe at 39.23 dB; scaled, 39.93.)
  // Groups (by FitPlan::group_ids) that stay at rest in every keyframe: their homographies
  // stay the identity and their fields zero (the warm starts pass them by and their gradients
  // are zeroed before Adam). A procedural target holds them exactly (motion_groups.h). Free
  // per-point offsets (deform: free) are not held.
  std::vector<std::string> held_groups;
  // The target's own motion, when the video stage made it (a procedural video's rigid bodies,
  // geometry/rigid_bodies.h): per path of the fitted scene the body that moves it (-1: none, or
  // empty), and per body its map from rest in every source frame (canvas units). A newly
  // activated keyframe is then also warm-started from where those maps put each point, and
  // kept when it fits the keyframe better than the copied and the flow-tracked starts: the
  // flow, sampled on a grid, follows a thin arm's swing only in part, and a hand or a
  // trident's head left a few pixels off collapsed where it was (man_demon).
  std::vector<int> known_body;
  std::vector<std::vector<Affine>> known_maps;
  FitOptions refined_at(double scale) const {
    FitOptions o = *this;
    const float s2 = static_cast<float>(scale * scale);
    o.w_smooth /= s2;
    o.w_contain /= s2;
    o.w_cohesion /= s2;
    o.contain_margin_px *= scale;
    if (o.lr_offsets == 0) o.lr_offsets = lr_refine_offsets;
    return o;
  }
};

struct LossTerms {
  float image = 0, smooth = 0, g1 = 0, contain = 0, cohesion = 0;
  float total() const { return image + smooth + g1 + contain + cohesion; }
};

// Everything needed to resume a fit (also what the checkpoint file holds).
struct FitState {
  int iteration = 0, active = 1;
  std::vector<int> steps;                       // Adam step per keyframe
  std::vector<float> params, m_params, v_params;
  std::vector<float> offsets, m_offsets, v_offsets;  // free per-point offsets
  std::vector<float> field, m_field, v_field;        // field coefficients
  // Where the schedule stands (Fitter::resume), so a resumed fit takes the very steps the
  // uninterrupted one would: whether the loss had stopped falling (a fit stopped after that,
  // in its refinement or while writing, goes straight on to them), the activation and plateau
  // tests' references and the learning rates' scale after rollbacks. `schedule` is false for
  // a checkpoint written before these were kept.
  bool schedule = false;
  bool converged = false;
  int last_activation = 0;
  float newest_ref = -1, lr_scale = 1;
  std::vector<float> plateau_ref;
};

class Fitter {
 public:
  // `scene` carries the colours to fit with (the target video's); `target` the keyframes at
  // the fitting size. Throws svgm::Error if the target's size does not match the scene's
  // render size at target.width. A target with no rgba (its holder keeps the frames packed)
  // leaves the loss without frames until read_targets_from.
  Fitter(ClRuntime& rt, const Scene& scene, const TargetFrames& target, const FitOptions& options);
  ~Fitter();

  // One scheduled iteration: activates a keyframe when due, then fit_iteration().
  LossTerms step();
  int iteration() const { return iteration_; }
  int active_keyframes() const { return active_; }
  int keyframes() const { return K_; }
  // The budget is spent, or the loss stopped falling (FitOptions::plateau_window).
  bool done() const { return iteration_ >= opt_.iterations || converged_; }
  bool converged() const { return converged_; }
  // The iteration at which the newest active keyframe was activated.
  int last_activation() const { return last_activation_; }
  // The iteration at which the paper's schedule activates keyframe k (adaptive activation
  // may activate it sooner: FitOptions::activation_window).
  int activation_iteration(int k) const;

  // Control points of every keyframe in canvas space: K * n_cp (x, y) pairs in the raster
  // plan's layout (path_cp_first / path_cp_count locate each path's points).
  std::vector<double> keyframe_points_canvas();
  // Premultiplied float renders of every active keyframe (for previews), K * H * W * 4.
  std::vector<float> render_keyframes();
  // Keyframe k's alone, H * W * 4 (the same bits as its part of render_keyframes; one not yet
  // active is drawn as its parameters stand): the final renders one at a time, 16 bytes per
  // pixel instead of per pixel and keyframe.
  std::vector<float> render_keyframe(int k);
  // Per-keyframe image losses of the last iteration.
  std::vector<float> keyframe_losses();
  // Per-keyframe image losses of the current parameters, every keyframe evaluated (active or
  // not); the next iteration recomputes what it needs.
  std::vector<float> evaluate_keyframe_losses();
  // Frees the loss's pixel-sized device memory (ClRaster::release_loss_buffers) while this
  // fitter only renders or waits for another; the next iteration or evaluation makes it again.
  void release_loss_memory();
  // Makes the loss's memory and constants from the target now, as the next iteration would
  // (ClRaster::prepare_loss): after this the target's rgba is not read again until
  // release_loss_memory, so its holder may set it aside (fit_stages.cpp's refinement).
  void prepare_loss_memory();
  // The loss reads the target's frames through `frame` (ClRaster::set_target_frames) instead of
  // its rgba, until read_targets_whole: its holder may pack them before the loss's constants
  // are made (the refinement: 16 bytes per pixel and keyframe less beside Q and R as they are made).
  void read_targets_from(std::function<void(int k, float* rgba)> frame);
  void read_targets_whole();

  const RasterPlan& raster_plan() const { return plan_; }
  const FitPlan& fit_plan() const { return fplan_; }
  const RenderSize& size() const { return size_; }

  FitState state();
  // The parameters and Adam's state of `s`; the schedule's tests start afresh from here (a
  // rollback, the refinement's guard).
  void restore(const FitState& s);
  // restore() and, when `s` has it, the schedule too (FitState::schedule): a resumed fit goes on
  // exactly as it would have (a converged one stays converged unless every iteration is asked).
  void resume(const FitState& s);
  // Multiplies both Adam learning rates by `s` from the next iteration on (the result gate's
  // rollback retries a diverged stretch with smaller steps).
  void scale_learning_rates(float s);

  // Canvas-independent start for a finer fit (coarse-to-fine, fit_job.h): the coarse fitter's
  // homographies, and as fixed base offsets its total per-point offsets (free + field) scaled
  // by `scale` (fine width / coarse width); this fitter's own field starts at zero on top of
  // them. Every keyframe becomes active with fresh Adam moments, at iteration 0.
  void adopt_coarse(Fitter& coarse, double scale);
  // Keyframes k with `which[k]` set become `other`'s (same drawing and keyframe count, `scale`
  // times narrower: its homographies, and its total offsets times `scale` with this fitter's
  // field zero there); every other keyframe, the iteration count and Adam's state are kept.
  // The refinement's guard puts back the coarse fit of a keyframe the refinement made worse.
  void take_keyframes(Fitter& other, double scale, const std::vector<char>& which);
  // Keyframes from the target (fit/optimise/keyframe_choice.h): this fit has more keyframes than
  // `other` (same drawing and width). Keyframe k starts as other's keyframe from[k] (its
  // homographies, its total offsets as fixed base offsets, this fitter's field zero); where
  // fresh[k] is set (a keyframe other did not have), it is then warm-started from there toward
  // its own frame (optical flow, as an activated keyframe is). Every keyframe becomes active
  // with fresh Adam moments, at iteration 0.
  void adopt_keyframes(Fitter& other, const std::vector<int>& from, const std::vector<char>& fresh);

  // Keyframe-to-keyframe flow from the tracker stage (flow_tracks.h): flows[k] moves keyframe
  // k-1's points to k for the warm start, instead of tracking the fit's own render.
  void set_flows(std::vector<FlowField> flows) { flows_ = std::move(flows); }

 private:
  LossTerms fit_iteration();
  void activate_keyframe(int k);
  // Optical-flow warm start of keyframe k (warm_start.h) from keyframe src as it stands (the
  // previous keyframe; k itself when its parameters were copied from elsewhere); keeps it
  // only if it fits better.
  void warm_start(int k, int src);
  // adopt_coarse with keyframe k taken from coarse's keyframe from[k].
  void adopt_coarse_from(Fitter& coarse, double scale, const std::vector<int>& from);
  // Keyframe k becomes other's keyframe from[k] where from[k] >= 0 (take_keyframes).
  void copy_keyframes(Fitter& other, double scale, const std::vector<int>& from);
  bool started_ = false;  // the first step was taken (keyframe 0's warm start is done)
  // The field increment of keyframe k that carries its tracked points where the tracks went
  // beyond their group's homography (field_warm_start.h); kept only if it fits better than
  // `before`, keyframe k's image loss as it stands.
  void warm_start_field(int k, const std::vector<int>& index, const PointTracks& tracks, float before);
  // `tracks` with the points of known rigid bodies (FitOptions::known_body) put where keyframe
  // k's map takes their rest positions; nothing when no point has a known body. `exact` marks
  // those points (per entry of `index`).
  std::optional<PointTracks> known_tracks(int k, const std::vector<int>& index, const PointTracks& tracks,
                                          std::vector<char>& exact) const;
  std::vector<int> cp_path_;  // path of every control point (-1: padding)
  float frame_loss(int k);  // image loss of keyframe k alone with the current parameters
  // Field and motion forward: control points of keyframes 0 .. frames-1 into the raster's buffer.
  void enqueue_motion(int frames);
  // Each keyframe's Adam bias-correction denominators (1 − β1^t, 1 − β2^t) from steps_, to
  // the device (kernels/adam.cl).
  void upload_steps();

  ClRuntime& rt_;
  FitOptions opt_;
  RenderSize size_;
  RasterPlan plan_;
  FitPlan fplan_;
  const TargetFrames& target_;
  int K_ = 0, G_ = 0;
  int iteration_ = 0, active_ = 1;
  std::vector<int> steps_;
  std::vector<cl_float2> bias_;  // upload_steps' host copy (the write does not block)
  std::vector<FlowField> flows_;
  std::unique_ptr<ClRaster> raster_;
  int real_cps_ = 0;  // control points that are not padding
  std::vector<char> held_group_;                  // FitOptions::held_groups, per fit group
  std::vector<std::pair<int, int>> held_nodes_;   // their field nodes: (first, count) runs
  void zero_held_gradients();
  float lr_scale_ = 1;
  // The plateau test: when the last keyframe became active, and each keyframe's image loss at
  // the start of the current window.
  void check_plateau();
  // Whether keyframe active_ is due: the paper's interval since the last activation has
  // passed, or the newest keyframe's loss has settled (FitOptions::activation_window).
  bool activation_due();
  float newest_ref_ = -1;  // the newest keyframe's loss at the start of the current window
  int last_activation_ = 0;
  std::vector<float> plateau_ref_;
  bool converged_ = false;
 public:
  // Warm starts tried and kept so far (for reports and tests).
  int warm_starts_tried = 0, warm_starts_kept = 0;
  int field_warm_starts_tried = 0, field_warm_starts_kept = 0;
  int known_starts_tried = 0, known_starts_kept = 0;  // from the target's known motion

 private:
  cl::Kernel k_motion_, k_motion_back_, k_smooth_, k_g1_, k_contain_, k_sum_, k_adam_p_, k_adam_o_,
      k_field_, k_field_back_, k_adam_f_, k_cohesion_;
  // offsets_: the free per-point offsets δ; total_offsets_: Δ = δ + field, what motion reads.
  cl::Buffer field_, total_offsets_, cp_node_first_, cp_node_, cp_node_w_, node_cp_first_, node_cp_,
      node_cp_w_, grad_field_, m_field_, v_field_, coh_first_, coh_nbr_, coh_len_, part_coh_;
  cl::Buffer params_, offsets_, rest_, cp_group_, cp_offset_, group_first_, group_cps_, nbr_first_,
      nbr_, nbr_w_, joints_, sdf_, grad_params_, grad_offsets_, m_params_, v_params_, m_offsets_,
      v_offsets_, bias_buf_, part_smooth_, part_contain_, contain_margin_, part_g1_, terms_;
};

// Initial homography parameters (identity about the group's rest centroid) for every group of
// one keyframe: G * 12 floats (kernels/motion.cl's layout).
std::vector<float> identity_motion(const FitPlan& fplan, const RasterPlan& plan, const RenderSize& size);

}  // namespace svgm
