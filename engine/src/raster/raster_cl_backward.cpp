// The OpenCL loss and backward routine of ClRaster: blurred MSE against target frames and
// exact gradients down to the control points (kernels/loss.cl, raster_backward.cl,
// stroke_backward.cl, flatten.cl).
#include <algorithm>
#include <cmath>

#include "raster/half_float.h"
#include "raster/launch_groups.h"
#include "raster/loss_tiles.h"
#include "raster/raster_cl.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {
// The tape pool's largest size in entries (float4): 2^27, 2 GiB, far above any drawing's need
// (a 1024 px frame with an edge on every pixel of every draw of a 100-draw scene is 10^8).
constexpr size_t kMaxPoolEntries = size_t{1} << 27;
// The loss chunk's residuals X' and E' (packed RGB floats, 12 bytes each, 24 bytes per pixel)
// take at most this many bytes: 5 frames at 512 px, 21 at 256 (a coarse fit of 15 keyframes
// is one chunk, as before the chunks). At 512 px, 21 keyframes held 176 MB of them (as float4);
// 32 MB is a few percent of a pass's time in launches more (ClRaster::set_loss_chunk_frames).
constexpr size_t kLossChunkBytes = size_t{32} << 20;
constexpr size_t kResidualPixelBytes = 3 * sizeof(float);  // X' or E' (kernels/loss.cl)
}  // namespace

void ClRaster::init_backward() {
  if (backward_ready_) return;
  const auto& p = plan_;
  const size_t K = static_cast<size_t>(frames_);
  const int n_draws = static_cast<int>(p.draws.size());
  const int n_chunks = static_cast<int>(p.chunk_lines.size() / 2);
  try {
    cl::Program& prog = *program_;
    k_blur_y_loss_ = cl::Kernel(prog, "blur_y_loss_rows");
    k_loss_total_ = cl::Kernel(prog, "loss_total");
    k_backward_ = cl::Kernel(prog, "raster_backward");
    k_taped_ = cl::Kernel(prog, "raster_taped");
    k_gather_lines_ = cl::Kernel(prog, "gather_line_grads");
    k_gather_points_ = cl::Kernel(prog, "gather_point_grads");
    k_stroke_back_ = cl::Kernel(prog, "stroke_backward");
    k_flatten_back_ = cl::Kernel(prog, "flatten_backward");

    if (chunk_ == 0)
      chunk_ = static_cast<int>(std::clamp<size_t>(kLossChunkBytes / (static_cast<size_t>(p.height) * p.width * 2 * kResidualPixelBytes), 1, K));
    make_loss_buffers();
    qsum_ = make(K * sizeof(float));
    ext_x_ = make(K * p.height * 2 * sizeof(int));
    ext_e_ = make(K * p.height * 2 * sizeof(int));
    row_sums_ = make(K * p.height * sizeof(float));
    loss_ = make((K + 1) * sizeof(float));
    overflow_ = make(sizeof(int));
    line_grad_ = make(K * p.n_lines * 4 * sizeof(float));
    grad_pts_ = make(K * p.n_pts * 2 * sizeof(float));
    grad_cp_ = make(K * p.n_cp * 2 * sizeof(float));
    line_chunk_ = make(p.line_chunk.size() * sizeof(int), p.line_chunk.data());
    pt_first_ = make(p.pt_first.size() * sizeof(int), p.pt_first.data());
    pt_entries_ = make(p.pt_entries.size() * sizeof(int), p.pt_entries.data());
    cp_first_ = make(p.cp_first.size() * sizeof(int), p.cp_first.data());
    cp_entries_ = make(p.cp_entries.size() * sizeof(int), p.cp_entries.data());

    // Local memory of the backward band: rows of accumulation, colour, transmittance (the
    // replay's running products), the two one-sided ∂L/∂a, the boundary marks and the
    // replay's last entry per pixel, and the tape in what is left, 24 bytes an entry (B and
    // the winding integral, the pixel and V). raster_taped needs less: no ∂L/∂a.
    const size_t rows_bytes = static_cast<size_t>(band_h_) *
                              ((p.width + 2) * sizeof(float) + p.width * (16 + 4 + 8 + 1 + 4));
    const size_t fixed = rows_bytes;
    constexpr size_t kEntryBytes = 4 * sizeof(float) + 2 * sizeof(float);
    if (fixed + 16 * 1024 > local_budget_)
      throw Error("the backward pass needs " + std::to_string(fixed + 16 * 1024) +
                  " bytes of local memory per band, the device offers " +
                  std::to_string(local_budget_));
    tape_cap_ = static_cast<int>((local_budget_ - fixed) / kEntryBytes);

    const int W = p.width, H = p.height, F = frames_;
    // The residual forward pass writes the x-blurred residual into image_; blur it along y
    // with the row sums of E² (kernels/loss.cl).
    set_args(k_blur_y_loss_, xres_, ext_x_, q_, resid_, ext_e_, row_sums_, W, H, F, qr_tiles_, loss_blur_);
    set_args(k_loss_total_, row_sums_, qsum_, loss_, 1.0f, H, F);
    set_args(k_backward_, lines_, draw_chunks_, chunk_lines_, draw_color_, draw_rule_, bounds_,
             resid_, ext_e_, r_, 1.0f, cl_float4{{0, 0, 0, 0}},
             cl::Local(static_cast<size_t>(band_h_) * (p.width + 2) * sizeof(float)),
             cl::Local(static_cast<size_t>(band_h_) * p.width * 4 * sizeof(float)),
             cl::Local(static_cast<size_t>(band_h_) * p.width * sizeof(float)),
             cl::Local(static_cast<size_t>(band_h_) * p.width * 2 * sizeof(float)),
             cl::Local(static_cast<size_t>(band_h_) * p.width),
             cl::Local(static_cast<size_t>(tape_cap_) * 4 * sizeof(float)), tape_cap_);
    // Arguments 18..20 (the pool) are set by resize_pool.
    set_args_at(k_backward_, 21, partial_, overflow_, p.n_lines, n_chunks, n_draws, bands_, W, H,
                draw_paint_, paint_, cl::Local(static_cast<size_t>(band_h_) * p.width * sizeof(int)),
                cl::Local(static_cast<size_t>(tape_cap_) * 2 * sizeof(float)));
    // Argument 33 (the pool's (pixel, V)) is set by resize_pool.
    set_args_at(k_backward_, 34, qr_tiles_, loss_blur_, chunk_snap_);
    pool_draw_ = make(K * bands_ * std::max<size_t>(n_draws, 1) * sizeof(int));
    pool_at_ = make(K * bands_ * 2 * sizeof(int));
    pool_used_ = make(K * sizeof(int));  // per chunk, at its first frame
    pool_asked_by_chunk_.assign(K, 0);
    set_args(k_taped_, lines_, draw_chunks_, chunk_lines_, draw_color_, draw_rule_, bounds_,
             cl::Local(static_cast<size_t>(band_h_) * (p.width + 2) * sizeof(float)),
             cl::Local(static_cast<size_t>(band_h_) * p.width * 4 * sizeof(float)),
             cl::Local(static_cast<size_t>(band_h_) * p.width),
             cl::Local(static_cast<size_t>(tape_cap_) * 4 * sizeof(float)), tape_cap_, xres_, ext_x_);
    // Argument 13 (background) is set per pass, 14..15 (the pool) by resize_pool.
    set_args_at(k_taped_, 16, pool_draw_, pool_at_, pool_used_, p.n_lines, n_chunks, n_draws, bands_, W, H,
                draw_paint_, paint_, cl::Local(static_cast<size_t>(band_h_) * p.width * sizeof(float)),
                cl::Local(static_cast<size_t>(band_h_) * p.width * sizeof(int)),
                cl::Local(static_cast<size_t>(tape_cap_) * 2 * sizeof(float)));
    // Argument 30 (the pool's (pixel, V)) is set by resize_pool.
    k_taped_.setArg(31, loss_blur_);
    k_taped_.setArg(32, chunk_snap_);
    // A first pool of a quarter of a chunk's pixels (it holds one chunk's tapes at a time); it
    // grows to what the bands of a chunk ask for.
    resize_pool(static_cast<int>(std::min<size_t>(static_cast<size_t>(chunk_) * p.height * p.width / 4 + 1, kMaxPoolEntries)));
    set_args(k_gather_lines_, lines_, line_chunk_, bounds_, partial_, line_grad_, p.n_lines,
             n_chunks, bands_, W, H);
    set_args(k_gather_points_, line_grad_, pt_first_, pt_entries_, grad_pts_, p.n_lines, p.n_pts);
    set_args(k_stroke_back_, pts_, grad_pts_, sp_a_, sp_b_, sp_f_, vert_join_,
             static_cast<int>(p.strokes.size()), p.n_pts);
    set_args(k_flatten_back_, grad_pts_, vert_w_, cp_first_, cp_entries_, grad_cp_, p.n_cp,
             p.n_pts);
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL setup of the backward pass failed on ") + rt_.info().name +
                ": " + e.what() + " " + cl_status_name(e.err()));
  }
  backward_ready_ = true;
}

void ClRaster::make_loss_buffers() {
  // Q and R (halves, by tiles) and their tile index: made at their size by
  // prepare_loss_constants, which knows how many tiles it stores.
  q_ = make(0);
  r_ = make(0);
  qr_pool_bytes_ = kMinBufferBytes;  // each pool's as counted (prepare_loss_constants)
  qr_tiles_ = make(0);
  // X' and E' for one chunk of frames (set_loss_chunk_frames).
  const size_t chunk_pixels = static_cast<size_t>(chunk_) * plan_.height * plan_.width;
  xres_ = make(chunk_pixels * kResidualPixelBytes);
  resid_ = make(chunk_pixels * kResidualPixelBytes);
  // The bands' partial gradients of the lines, a chunk's frames only: gather_line_grads sums
  // them after each chunk's backward pass (every frame's were 20 MB for the bundled example's
  // 21 keyframes at 512 px, K x lines x bands x 16 B).
  partial_ = make(static_cast<size_t>(chunk_) * plan_.n_lines * static_cast<size_t>(bands_) * 4 * sizeof(float));
  if (!backward_ready_) return;  // init_backward binds them with the rest
  set_args_at(k_blur_y_loss_, 0, xres_);
  set_args_at(k_taped_, 11, xres_);
  // Made again after release_loss_buffers: bound where init_backward bound them, and the pool
  // at the capacity it had grown to (what the bands asked for stays what they ask for).
  set_args_at(k_blur_y_loss_, 2, q_, resid_);
  set_args_at(k_blur_y_loss_, 9, qr_tiles_);
  set_args_at(k_backward_, 6, resid_);
  set_args_at(k_backward_, 8, r_);
  set_args_at(k_backward_, 34, qr_tiles_);
  set_args_at(k_backward_, 21, partial_);
  set_args_at(k_gather_lines_, 3, partial_);
  resize_pool(pool_cap_);
}

void ClRaster::release_loss_buffers() {
  if (!q_()) return;
  finish_pool_read();
  rt_.queue().finish();  // nothing enqueued still uses them
  // The Float renders' image_ too: a fitter that waits or only renders makes it again.
  for (cl::Buffer* b : {&q_, &r_, &qr_tiles_, &xres_, &resid_, &partial_, &pool_, &pool_aux_, &image_}) {
    if (!(*b)()) continue;
    device_bytes_ -= b == &q_ || b == &r_ ? qr_pool_bytes_ : b->getInfo<CL_MEM_SIZE>();
    *b = cl::Buffer();
  }
  q_background_ = {-1, -1, -1, -1};  // Q and R are made again on the next loss pass
}

void ClRaster::resize_pool(int entries) {
  if (pool_()) device_bytes_ -= static_cast<size_t>(std::max(pool_cap_, 1)) * 4 * sizeof(float);
  if (pool_aux_()) device_bytes_ -= static_cast<size_t>(std::max(pool_cap_, 1)) * 2 * sizeof(float);
  pool_cap_ = std::max(entries, 0);
  // An entry: B and the winding integral (float4) in pool_, its pixel and V (float2) in
  // pool_aux_ (kernels/raster_backward.cl).
  pool_ = make(static_cast<size_t>(std::max(pool_cap_, 1)) * 4 * sizeof(float));
  pool_aux_ = make(static_cast<size_t>(std::max(pool_cap_, 1)) * 2 * sizeof(float));
  set_args_at(k_taped_, 14, pool_, pool_cap_);
  set_args_at(k_taped_, 30, pool_aux_);
  set_args_at(k_backward_, 18, pool_, pool_draw_, pool_at_);
  set_args_at(k_backward_, 33, pool_aux_);
}

bool ClRaster::finish_pool_read() {
  if (!pool_read_()) return false;
  pool_read_.wait();
  pool_read_ = cl::Event();
  // The most a chunk's bands asked for (each chunk's count is at its first frame; the rest 0).
  pool_asked_ = *std::max_element(pool_asked_by_chunk_.begin(), pool_asked_by_chunk_.end());
  return true;
}

void ClRaster::set_tape_pool_capacity(int entries) {
  init_backward();
  finish_pool_read();  // the last pass's request must not regrow the pool before the next pass
  resize_pool(entries);
}

int ClRaster::tape_pool_misses() {
  std::vector<cl_int2> at(static_cast<size_t>(active_) * bands_);
  rt_.queue().enqueueReadBuffer(pool_at_, CL_TRUE, 0, at.size() * sizeof(cl_int2), at.data());
  return static_cast<int>(std::count_if(at.begin(), at.end(), [](const cl_int2& a) { return a.s[0] < 0; }));
}

int ClRaster::tape_pool_entries() {
  finish_pool_read();
  return pool_asked_;
}

void ClRaster::set_loss_chunk_frames(int n) {
  if (n < 1) throw Error("internal: loss chunk of " + std::to_string(n) + " frames");
  release_loss_buffers();
  chunk_ = std::min(n, frames_);
}

void ClRaster::forward_taped(const std::array<float, 4>& background) {
  // The bands' request of the previous pass (read without blocking; done by now): grow the
  // pool by a quarter beyond it, so a fit whose drawing moves does not regrow every pass.
  if (finish_pool_read() && pool_asked_ > pool_cap_)
    resize_pool(static_cast<int>(std::min<size_t>(static_cast<size_t>(pool_asked_) * 5 / 4, kMaxPoolEntries)));
  events_.clear();
  auto& q = rt_.queue();
  k_taped_.setArg(13, cl_float4{{background[0], background[1], background[2], background[3]}});
  q.enqueueFillBuffer(pool_used_, 0, 0, static_cast<size_t>(frames_) * sizeof(int));
  enqueue_geometry();
}

void ClRaster::set_targets(const std::vector<float>& rgba) {
  const size_t want = static_cast<size_t>(frames_) * plan_.height * plan_.width * 4;
  if (rgba.size() != want)
    throw Error("internal: target upload of " + std::to_string(rgba.size()) + " floats, expected " +
                std::to_string(want));
  const size_t frame = static_cast<size_t>(plan_.height) * plan_.width * 4;
  set_target_frames([&rgba, want, frame](int k, float* out) {
    if (rgba.size() != want) throw Error("internal: the loss's targets are gone or resized (set_targets keeps no copy)");
    std::copy_n(rgba.begin() + static_cast<std::ptrdiff_t>(k * frame), frame, out);
  });
}

void ClRaster::set_target_frames(TargetFrameReader frame) {
  init_backward();
  targets_ = std::move(frame);
  q_background_ = {-1, -1, -1, -1};  // recompute the loss constants on next use
}

void ClRaster::target_frame(int k, float* rgba) const {
  if (!targets_) throw Error("internal: a target frame read before the targets were set");
  targets_(k, rgba);
}

void ClRaster::prepare_loss_constants(const std::array<float, 4>& bg) {
  if (bg == q_background_) return;
  const int W = plan_.width, H = plan_.height, K = frames_;
  const size_t px = static_cast<size_t>(W) * H;
  if (!targets_) throw Error("internal: loss without targets (set_targets)");
  std::vector<float> frame(px * 4);  // one target frame at a time
  // The render's blur B (loss.cl's taps; per channel group with a chroma σ of its own,
  // raster/loss_taps.h render_blur) and the target's, in double: Q = bg·(G_t 1) − G_t ∗ T,
  // R = Bᵀ Q. The paper is blurred as the target is, B only acting on what is drawn (X): with
  // zero padding, bg·(B 1) − bg·(G_t 1) was a band along the frame's border wherever blur
  // matching widened B, the same at every pose: a floor under the loss (a blurred bat's loss
  // at rest 7.3e-5 against 2.8e-6 clean) that the relative plateau and activation tests
  // (optimise/fitter.h) read as a loss that had stopped falling.
  const std::vector<double> g_target = loss_stencil(kLossSigma);
  // Above σ 1 both blurs pad by reflection (loss_taps.h, loss_reflects): then G_t 1 = 1, and a
  // target's ink that runs off the frame stays as dark to the border as the render's.
  const bool reflect = loss_reflects(render_sigma_);
  const std::vector<double> g1 = blur_rgb(std::vector<double>(px * 3, 1.0), W, H, g_target, reflect);
  std::vector<double> q(px * 3);
  // One frame's Q and R at a time, kept by tiles (raster/loss_tiles.h): whole-clip host copies
  // were 32 bytes per pixel and frame at the fit's peak (176 MB for 21 keyframes at 512 px),
  // the dense device copies 16 (88 MB).
  std::vector<uint16_t> qh(px * 4, 0), rh(px * 4, 0);
  std::vector<float> qsum(K);
  // The device's layout (loss.cl's loss_tile_pixel): Q's pool and R's, each every frame's
  // stored tiles in frame order, then the uniform tiles' values, a pixel each; the index holds,
  // per frame and tile, the tile's number in the pool, or −1 − c for the value at pool pixel c.
  // Each frame's stored tiles go to the device as they are made (a frame's host copy at a time:
  // all of them held until the pools' size was known were the twemoji dog's peak with 34
  // keyframes at 512 px), into pools reserved at the most they could take (every tile and a
  // value per tile): a reservation's pages past what is written are never touched, so never
  // resident, and device_bytes() counts what is written.
  constexpr size_t kTilePixels = size_t{kLossTile} * kLossTile;
  const size_t tile_bytes = kTilePixels * 4 * sizeof(uint16_t);
  const size_t per_frame = static_cast<size_t>((W + kLossTile - 1) / kLossTile) * ((H + kLossTile - 1) / kLossTile);
  const size_t most_tiles = static_cast<size_t>(K) * per_frame;
  // The reservation is capped at the device's largest buffer (a GPU's is a quarter of its
  // memory or so): what is stored never exceeded one buffer before either, and only a
  // reservation past the cap that the stored tiles would not have filled is spared.
  const size_t largest = rt_.device().getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>() / tile_bytes * tile_bytes;
  const size_t reserve = std::min((most_tiles + (most_tiles + kTilePixels - 1) / kTilePixels) * tile_bytes, largest);
  const auto check_fits = [&](size_t end) {
    if (end > reserve)
      throw Error("the loss constants of " + std::to_string(K) + " frames at " + std::to_string(W) + "x" + std::to_string(H) +
                  " px need more than the device's largest buffer (" + std::to_string(largest >> 20) +
                  " MB): fewer keyframes or a smaller fitting size");
  };
  device_bytes_ -= 2 * qr_pool_bytes_ + qr_tiles_.getInfo<CL_MEM_SIZE>();
  q_ = cl::Buffer(rt_.context(), CL_MEM_READ_WRITE, reserve);
  r_ = cl::Buffer(rt_.context(), CL_MEM_READ_WRITE, reserve);
  auto& queue = rt_.queue();
  std::vector<std::vector<int>> frame_tiles(static_cast<size_t>(K));
  std::vector<std::vector<std::array<uint16_t, 8>>> frame_values(static_cast<size_t>(K));
  std::vector<size_t> first_stored(static_cast<size_t>(K));
  size_t n_stored = 0;
  for (int k = 0; k < K; ++k) {
    targets_(k, frame.data());
    {
      // The target and its blur are freed before R is made: each temporary here is a frame of
      // doubles (6.3 MB at 512 px), and this loop was the fit's peak (issue 38).
      std::vector<double> t(px * 3);
      for (size_t p = 0; p < px; ++p)
        for (int c = 0; c < 3; ++c) t[3 * p + c] = frame[p * 4 + c];
      const std::vector<double> gt = blur_rgb(t, W, H, g_target, reflect);
      t = std::vector<double>();
      // Q as the device stores it (a half, within 2^-11 of it: a twentieth of an 8-bit level),
      // so that Σ Q² and R are those of the Q the loss reads and Σ E² stays a sum of squares.
      for (size_t i = 0; i < q.size(); ++i) {
        const uint16_t h = float_to_half(static_cast<float>(bg[i % 3] * g1[i] - gt[i]));
        qh[i / 3 * 4 + i % 3] = h;
        q[i] = half_to_float(h);
      }
    }
    // With a chroma weight the metric M (loss.cl's loss_metric): Σ Qᵀ M Q and R = Bᵀ M Q.
    double sum = 0;
    std::vector<double> r;
    if (chroma_weight_ != 1) {
      const std::vector<double> mq = chroma_metric(q, chroma_weight_);
      for (size_t i = 0; i < q.size(); ++i) sum += q[i] * mq[i];
      r = render_blur(mq, W, H, render_sigma_, chroma_sigma_, true, reflect);
    } else {
      for (size_t i = 0; i < q.size(); ++i) sum += q[i] * q[i];
      r = render_blur(q, W, H, render_sigma_, chroma_sigma_, true, reflect);
    }
    qsum[k] = static_cast<float>(sum);
    for (size_t i = 0; i < r.size(); ++i) rh[i / 3 * 4 + i % 3] = float_to_half(static_cast<float>(r[i]));
    r = std::vector<double>();
    LossTiles f = tile_loss_frame(qh.data(), rh.data(), W, H, every_loss_tile_);
    const size_t bytes = f.q.size() * sizeof(uint16_t);
    check_fits(n_stored * tile_bytes + bytes);
    if (bytes) {
      queue.enqueueWriteBuffer(q_, CL_TRUE, n_stored * tile_bytes, bytes, f.q.data());
      queue.enqueueWriteBuffer(r_, CL_TRUE, n_stored * tile_bytes, bytes, f.r.data());
    }
    first_stored[static_cast<size_t>(k)] = n_stored;
    n_stored += static_cast<size_t>(f.stored());
    frame_tiles[static_cast<size_t>(k)] = std::move(f.tile);
    frame_values[static_cast<size_t>(k)] = std::move(f.values);
  }
  // The values after the stored tiles; the index made now that their place is known.
  std::vector<int> index(most_tiles);
  std::vector<uint16_t> consts_q, consts_r;
  for (int k = 0; k < K; ++k) {
    const size_t base = n_stored * kTilePixels + consts_q.size() / 4;
    const std::vector<int>& tile = frame_tiles[static_cast<size_t>(k)];
    for (size_t i = 0; i < per_frame; ++i)
      index[k * per_frame + i] = tile[i] >= 0 ? static_cast<int>(first_stored[static_cast<size_t>(k)]) + tile[i]
                                              : -1 - static_cast<int>(base + static_cast<size_t>(-1 - tile[i]));
    for (const auto& v : frame_values[static_cast<size_t>(k)]) {
      consts_q.insert(consts_q.end(), v.begin(), v.begin() + 4);
      consts_r.insert(consts_r.end(), v.begin() + 4, v.end());
    }
  }
  check_fits(n_stored * tile_bytes + consts_q.size() * sizeof(uint16_t));
  if (!consts_q.empty()) {
    queue.enqueueWriteBuffer(q_, CL_TRUE, n_stored * tile_bytes, consts_q.size() * sizeof(uint16_t), consts_q.data());
    queue.enqueueWriteBuffer(r_, CL_TRUE, n_stored * tile_bytes, consts_r.size() * sizeof(uint16_t), consts_r.data());
  }
  const size_t c0 = (consts_q.size() / 4 + kTilePixels - 1) / kTilePixels;  // the values' tiles
  qr_pool_bytes_ = std::max((n_stored + c0) * tile_bytes, kMinBufferBytes);
  device_bytes_ += 2 * qr_pool_bytes_;
  qr_tiles_ = make(index.size() * sizeof(int));
  queue.enqueueWriteBuffer(qr_tiles_, CL_TRUE, 0, index.size() * sizeof(int), index.data());
  queue.enqueueWriteBuffer(qsum_, CL_TRUE, 0, qsum.size() * sizeof(float), qsum.data());
  loss_tiles_stored_ = n_stored;
  set_args_at(k_blur_y_loss_, 2, q_);
  set_args_at(k_blur_y_loss_, 9, qr_tiles_);
  set_args_at(k_backward_, 8, r_);
  set_args_at(k_backward_, 34, qr_tiles_);
  q_background_ = bg;
}

float ClRaster::loss_and_gradient(float weight, const std::array<float, 4>& background) {
  enqueue_loss_and_gradient(weight, background);
  return read_loss();
}

float ClRaster::read_loss() {
  float loss = 0;
  rt_.queue().enqueueReadBuffer(loss_, CL_TRUE, 0, sizeof(float), &loss);
  return loss;
}

void ClRaster::prepare_loss(const std::array<float, 4>& background) {
  init_backward();
  if (!targets_) throw Error("internal: loss without targets (set_targets)");
  if (!q_()) make_loss_buffers();
  prepare_loss_constants(background);
}

void ClRaster::enqueue_loss_and_gradient(float weight, const std::array<float, 4>& background) {
  prepare_loss(background);
  const auto& p = plan_;
  const size_t K = static_cast<size_t>(active_);
  const size_t pixels = K * p.height * static_cast<size_t>(p.width);
  const cl_float4 bg{{background[0], background[1], background[2], background[3]}};
  // L = weight / N · Σ E², N = K·H·W·3; ∂L/∂C = blur(2 · weight / N · E).
  const float scale = weight / static_cast<float>(pixels * 3);
  try {
    forward_taped(background);
    auto& q = rt_.queue();
    k_backward_.setArg(9, 2.0f * scale);
    k_backward_.setArg(10, bg);
    k_loss_total_.setArg(3, scale);
    k_loss_total_.setArg(5, active_);
    k_blur_y_loss_.setArg(8, active_);
    q.enqueueFillBuffer(overflow_, 0, 0, sizeof(int));
    // A chunk of frames at a time (the launch's offset is its first frame): X' and E', the
    // tapes and the lines' partial gradients are the chunk's; the row sums every frame's. Each
    // frame's sums are its own, so the chunks give the same bits as one pass over every frame.
    for (int k0 = 0; k0 < active_; k0 += chunk_) {
      const int n = std::min(chunk_, active_ - k0);
      launch("raster_taped", k_taped_, cl::NDRange(bands_ * group_, n), cl::NDRange(group_, 1), cl::NDRange(0, k0));
      launch("blur_y_loss_rows", k_blur_y_loss_, cl::NDRange(round_up(p.height, 16), n), kRowGroup,
             cl::NDRange(0, k0));
      launch("raster_backward", k_backward_, cl::NDRange(bands_ * group_, n), cl::NDRange(group_, 1),
             cl::NDRange(0, k0));
      launch("gather_line_grads", k_gather_lines_, cl::NDRange(round_up(p.n_lines, 64), n), cl::NullRange,
             cl::NDRange(0, k0));
    }
    launch("loss_total", k_loss_total_, cl::NDRange(1));
    launch("gather_point_grads", k_gather_points_, cl::NDRange(round_up(p.n_pts, 64), K));
    if (!p.strokes.empty())
      launch("stroke_backward", k_stroke_back_, cl::NDRange(round_up(p.strokes.size(), 8), K), kStrokeGroup);
    launch("flatten_backward", k_flatten_back_, cl::NDRange(round_up(p.n_cp, 64), K));
    q.enqueueReadBuffer(pool_used_, CL_FALSE, 0, static_cast<size_t>(frames_) * sizeof(int), pool_asked_by_chunk_.data(),
                        nullptr, &pool_read_);
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL backward pass failed on ") + rt_.info().name + ": " +
                e.what() + " " + cl_status_name(e.err()));
  }
}

std::vector<float> ClRaster::read_frame_losses() {
  std::vector<float> out(static_cast<size_t>(active_) + 1);
  rt_.queue().enqueueReadBuffer(loss_, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  out.erase(out.begin());
  return out;
}

std::vector<float> ClRaster::read_cp_gradient() {
  std::vector<float> out(static_cast<size_t>(frames_) * plan_.n_cp * 2);
  rt_.queue().enqueueReadBuffer(grad_cp_, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  return out;
}

std::vector<float> ClRaster::read_point_gradient() {
  std::vector<float> out(static_cast<size_t>(frames_) * plan_.n_pts * 2);
  rt_.queue().enqueueReadBuffer(grad_pts_, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  return out;
}

int ClRaster::tape_overflow() {
  int v = 0;
  rt_.queue().enqueueReadBuffer(overflow_, CL_TRUE, 0, sizeof(int), &v);
  return v;
}

}  // namespace svgm
