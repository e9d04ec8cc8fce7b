// The OpenCL forward rasteriser: one host routine that executes a RasterPlan for K frames.
//
// Per batch: flatten (F = B P) -> stroke (outline points) -> gather_lines -> chunk_bounds ->
// raster (coverage + compositing per band of rows). All buffers stay on the device; the host enqueues
// the five launches on an in-order queue and only reads back what is asked for. A fit's pass
// (enqueue_loss_and_gradient) runs raster_taped instead of raster, which also tapes what the
// backward pass needs, then the loss and the backward kernels (raster_cl_backward.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "opencl/runtime.h"
#include "raster/loss_taps.h"
#include "raster/raster_plan.h"

namespace svgm {

class ClRaster {
 public:
  // `render_sigma`: the σ of the Gaussian the loss blurs the render with (kernels/loss.cl; the
  // target's is always kLossSigma). Above it, blur matching (fit/target/blur_match.h).
  // `chroma_sigma`: the σ of the render's chroma blur in YCbCr (raster/loss_taps.h,
  // render_blur); 0 means render_sigma, the plain blur of every channel alike.
  // `chroma_weight` (0, 1]: how much a residual of chroma alone counts against one of luma
  // (kernels/loss.cl's loss_metric; 1, the plain squared error). Any blur but the paper's
  // (σ 1, every channel alike, weight 1) runs on one program (raster/loss_blur.h).
  ClRaster(ClRuntime& rt, const RasterPlan& plan, int frames, double render_sigma = kLossSigma,
           double chroma_sigma = 0, double chroma_weight = 1);

  int frames() const { return frames_; }
  // Launches cover the first `n` frames only (1..frames()): the fitter activates keyframes
  // progressively, and the loss is the mean over the active ones.
  void set_active_frames(int n);
  int active_frames() const { return active_; }
  // The device buffers of control points ([K][n_cp] float2) and of ∂L/∂(control points), for
  // stages that produce or consume them on the device (the fitter's motion model).
  cl::Buffer& cp_buffer() { return cp_; }
  const RasterPlan& plan() const { return plan_; }

  // Uploads control points for all frames: frames * n_cp (x, y) pairs.
  void set_control_points(const std::vector<float>& cp);
  // Uploads the plan's rest pose into every frame.
  void set_rest_pose();

  // Values match OUT_* in kernels/raster.cl.
  enum class Output { Float = 0, Rgba8 = 1, Residual = 2 };
  // Enqueues the forward pass; returns at once (the queue is in order). Float keeps
  // premultiplied float RGBA images (read_image); Rgba8 writes 8-bit straight RGBA over
  // `background`, premultiplied ({1,1,1,1} white, {0,0,0,0} transparent) (read_rgba8);
  // Residual writes (image over background) − target, the loss's first step.
  void forward(Output output = Output::Float, const std::array<float, 4>& background = {});
  // Blocks until the queue is idle.
  void finish();

  // Reads the 8-bit images of the last Rgba8 forward: frames * height * width * 4 bytes.
  std::vector<uint8_t> read_rgba8();
  // Reads the premultiplied float RGBA images: frames * height * width * 4 floats.
  std::vector<float> read_image();
  // Frame k of them only: height * width * 4 floats (a 21-keyframe clip at 512 px is 88 MB).
  std::vector<float> read_image_frame(int k);
  // Frees the Float images (16 bytes per pixel and frame, in host memory under PoCL) once they
  // are read; the next Float forward makes them again.
  void release_image();
  // Premultiplied float RGBA renders of frames first .. first + count − 1 alone, over
  // `background` (count * height * width * 4 floats, the bits a Float forward gives those
  // frames): the launches are offset to them and the device holds only their images, freed
  // before this returns. Frames at or past active_frames() are drawn too (their control points
  // as they stand).
  std::vector<float> render_frames(int first, int count, const std::array<float, 4>& background);
  // The same bits into `out` (resized; its memory reused) through a device image kept between
  // calls until release_image(), for a caller that draws frame after frame (a procedural
  // candidate: 49 frames at 512 px). A new 4 MB host and device image per frame faulted in all
  // their pages whenever glibc had returned the last ones to the system (it trims the heap's top):
  // half of the first candidates' time, which made the video stage's ETA 2.4x too long.
  void render_frames_into(int first, int count, const std::array<float, 4>& background, std::vector<float>& out);

  // With a profiling runtime: milliseconds each kernel of the last forward() took on the device.
  std::vector<std::pair<std::string, double>> kernel_times() const;

  // ---- Gradients (raster_cl_backward.cpp) ----
  // Takes the K target frames: frames * height * width RGBA floats (straight RGB, A unused).
  // No copy is kept (16 bytes per pixel and frame: 88 MB for 21 keyframes at 512 px): `rgba`
  // must stay alive and unchanged while losses are computed against it (the loss's constants
  // are made from it on the next loss pass, and again after release_loss_buffers).
  void set_targets(const std::vector<float>& rgba);
  void set_targets(std::vector<float>&&) = delete;  // a temporary would be gone by the loss
  // The same targets read a frame at a time: `frame(k, out)` writes frame k's height * width
  // RGBA floats to `out`, whenever the loss's constants are made (as above). For a holder that
  // keeps them packed (fit/target/white_runs.h): the whole clip's floats are never needed.
  using TargetFrameReader = std::function<void(int k, float* rgba)>;
  void set_target_frames(TargetFrameReader frame);
  // Frame k of the targets as the loss reads them (either form above), into `rgba`.
  void target_frame(int k, float* rgba) const;
  // Frees the loss's pixel-sized device buffers (Q and R in half precision, the residuals X'
  // and E', the tape pool and the bands' partial gradients: 48 bytes and more per pixel and
  // frame, held in host memory by PoCL) until the next loss pass makes them again, from the
  // targets. For a fitter that only renders from here on, or waits while another one fits. The
  // last pass's losses stay readable.
  void release_loss_buffers();
  bool holds_loss_buffers() const { return q_(); }
  // Makes the loss buffers and the constants Q and R for `background` now, as the next loss
  // pass would: from here until release_loss_buffers (or another background) the targets are
  // not read, and a pass that would need them after all throws instead of reading them.
  void prepare_loss(const std::array<float, 4>& background);
  // Forward pass, blurred-MSE loss against the targets (kernels/loss.cl) and the backward pass
  // down to the control points, all on the device; returns the loss (reading one scalar).
  // `weight` multiplies the mean of the squared blurred residual; the frames are composited
  // over `background` (premultiplied).
  float loss_and_gradient(float weight, const std::array<float, 4>& background);
  // The same without waiting: enqueues everything; the loss is read later with read_loss().
  void enqueue_loss_and_gradient(float weight, const std::array<float, 4>& background);
  float read_loss();
  // Per-frame losses of the last loss_and_gradient (each already weighted).
  std::vector<float> read_frame_losses();
  // ∂L/∂(control points): frames * n_cp (x, y) pairs, of the last loss_and_gradient.
  std::vector<float> read_cp_gradient();
  // ∂L/∂(points) pairs, for tests.
  std::vector<float> read_point_gradient();
  cl::Buffer& cp_gradient_buffer() { return grad_cp_; }
  // Largest tape a band needed beyond its capacity in the last backward pass (0: none). The
  // gradient of an overflowing band misses the pixels past the capacity.
  int tape_overflow();
  // For tests: the tape pool's capacity in entries (0: every band replays its forward pass in
  // the backward kernel). The pool grows again to what the bands asked for on the next call.
  void set_tape_pool_capacity(int entries);
  // Bands of the last pass whose tape was not in the pool (raster_backward replayed them).
  int tape_pool_misses();
  // For tests: the entries the last pass's bands put in the pool (the most of any chunk of
  // frames). Entries whose draw is hidden at their pixel are not among them
  // (kernels/raster_backward.cl, drop_hidden_entries).
  int tape_pool_entries();
  // The loss pass runs raster_taped, the y-blur and raster_backward over this many frames at a
  // time, so the residuals X' and E' (24 bytes per pixel) exist for those frames only: at most
  // kLossChunkBytes of them, whatever the clip's length (the same bits for any count: each
  // frame's sums and gradients are its own, added in frame order after). For tests: set it
  // (n >= 1); the buffers are made again at that size on the next loss pass.
  void set_loss_chunk_frames(int n);
  int loss_chunk_frames() const { return chunk_; }

  // Q and R are held by tiles (raster/loss_tiles.h): those of the frames' tiles that are not
  // their frame's constant. For tests: `every` stores every tile (the dense layout by tiles;
  // the same bits), from the next loss pass whose constants are made.
  void set_every_loss_tile(bool every) { every_loss_tile_ = every; q_background_ = {-1, -1, -1, -1}; }
  size_t loss_tiles_stored() const { return loss_tiles_stored_; }

  // Bytes of device memory this routine allocated.
  size_t device_bytes() const { return device_bytes_; }

 private:
  cl::Buffer make(size_t bytes, const void* host = nullptr);
  void launch(const char* name, cl::Kernel& k, const cl::NDRange& global,
              const cl::NDRange& local = cl::NullRange, const cl::NDRange& offset = cl::NullRange);
  void init_backward();
  // The buffers release_loss_buffers frees, made and bound to the kernels' arguments.
  void make_loss_buffers();
  // flatten, stroke, gather_lines and chunk_bounds for the active frames.
  void enqueue_geometry();
  // The same for frames first .. first + count − 1.
  void enqueue_geometry(int first, int count);
  // The fit's forward pass (kernels/raster_backward.cl, raster_taped): the residual output and
  // each band's tape, kept in the tape pool for raster_backward.
  void forward_taped(const std::array<float, 4>& background);

  ClRuntime& rt_;
  RasterPlan plan_;
  int frames_;
  int active_ = 0;
  double render_sigma_ = kLossSigma;
  double chroma_sigma_ = kLossSigma;  // = render_sigma_ unless the chroma blur is its own
  double chroma_weight_ = 1;          // loss.cl's loss_metric
  cl::Buffer loss_blur_;              // the kernels' LossBlur (raster/loss_blur.h)
  int band_h_ = 16, bands_ = 0, group_ = 1;
  size_t device_bytes_ = 0;
  std::vector<std::pair<std::string, cl::Event>> events_;
  size_t local_budget_ = 0;
  cl::Program* program_ = nullptr;

  bool backward_ready_ = false;
  int tape_cap_ = 0;
  // The tape pool (raster_taped -> raster_backward): one chunk of frames' tapes (the loss
  // pass's chunks take turns: a pool of 24 bytes an entry for every frame's tapes was 31 MB for
  // the bundled example's 21 keyframes at 512 px), each band's per-draw offsets and its
  // (offset, length), the entries each chunk's bands asked for (at its first frame), those
  // counts as last read, and their largest.
  cl::Kernel k_taped_;
  cl::Buffer pool_, pool_aux_, pool_draw_, pool_at_, pool_used_;
  int pool_cap_ = 0;
  std::vector<int> pool_asked_by_chunk_;
  int pool_asked_ = 0;
  cl::Event pool_read_;
  void resize_pool(int entries);
  // Waits for the pending read of pool_asked_, if any; returns whether there was one.
  bool finish_pool_read();
  cl::Kernel k_blur_y_loss_, k_loss_total_, k_backward_, k_gather_lines_,
      k_gather_points_, k_stroke_back_, k_flatten_back_;
  // The loss's constant parts (kernels/loss.cl): Q = bg·(G∗1) − G∗T, R = G∗Q, Σ Q² per frame,
  // for the background they were made for; and the row extents of X' and E'.
  TargetFrameReader targets_;  // the caller's frames (set_targets, set_target_frames)
  std::array<float, 4> q_background_{-1, -1, -1, -1};
  void prepare_loss_constants(const std::array<float, 4>& background);
  cl::Buffer q_, r_, qsum_, ext_x_, ext_e_;
  cl::Buffer qr_tiles_;  // per frame and tile: its number in q_ and r_, or −1 − frame
  bool every_loss_tile_ = false;
  size_t loss_tiles_stored_ = 0;
  // What device_bytes_ counts for each of Q's and R's pools: what is written of them (their
  // reservation's other pages are never touched; prepare_loss_constants).
  size_t qr_pool_bytes_ = 0;
  // The loss chunk's residuals (set_loss_chunk_frames): X' (the x-blurred render, written by
  // raster_taped) and E' (resid_, its y-blur), chunk_ frames each.
  int chunk_ = 0;  // 0: chosen by init_backward
  cl::Buffer xres_;
  cl::Buffer resid_, row_sums_, loss_, partial_, overflow_,
      line_grad_, grad_pts_, grad_cp_, line_chunk_, pt_first_, pt_entries_, cp_first_,
      cp_entries_;
  cl::Kernel k_flatten_, k_stroke_, k_lines_, k_bounds_, k_raster_;
  cl::Buffer cp_, vert_cp_, vert_w_, vert_join_, sp_a_, sp_b_, sp_f_, pts_, line_ab_, lines_,
      draw_chunks_, chunk_lines_, draw_color_, draw_rule_, bounds_, chunk_snap_, acc_, image_, rgba_,
      draw_paint_, paint_, render_image_;
  void render_into(int first, int count, const std::array<float, 4>& background, cl::Buffer& img, std::vector<float>& out);
};

}  // namespace svgm
