// The OpenCL forward rasteriser routine (see raster_cl.h and kernels/*.cl for the maths).
#include "raster/raster_cl.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "opencl/tuning.h"
#include "raster/launch_groups.h"
#include "raster/loss_blur.h"
#include "raster/loss_tiles.h"
#include "svgmotion/error.h"

namespace svgm {

cl::Buffer ClRaster::make(size_t bytes, const void* host) {
  device_bytes_ += std::max(bytes, kMinBufferBytes);
  if (host) return input_buffer(rt_.context(), host, bytes);
  return cl::Buffer(rt_.context(), CL_MEM_READ_WRITE, std::max(bytes, kMinBufferBytes));
}

ClRaster::ClRaster(ClRuntime& rt, const RasterPlan& plan, int frames, double render_sigma, double chroma_sigma,
                   double chroma_weight)
    : rt_(rt),
      plan_(plan),
      frames_(frames),
      active_(frames),
      render_sigma_(render_sigma),
      chroma_sigma_(chroma_sigma > 0 ? chroma_sigma : render_sigma),
      chroma_weight_(chroma_weight) {
  if (frames < 1) throw Error("frame count must be at least 1");
  if (!(chroma_weight > 0 && chroma_weight <= 1)) throw Error("the chroma weight must be in (0, 1]");
  const auto& p = plan_;
  const size_t K = static_cast<size_t>(frames);
  const RasterTuning tuning = raster_tuning(rt_.info(), p.width);
  band_h_ = tuning.band_height;
  group_ = tuning.group_size;
  bands_ = (p.height + band_h_ - 1) / band_h_;
  try {
    // One program for the forward and backward kernels: PoCL compiles it once, then the
    // binary comes from the cache. The paper's blur is compiled in; every other blur shares
    // the LOSS_MATCHED build, its taps an argument (raster/loss_blur.h).
    // Missing from the cache, it is compiled in a child (opencl/compile_child.h) told how to
    // make the same program: `svgmotion devices --warm-for` makes a ClRaster of this width,
    // height and blur, and launches every kernel as this one will.
    char child_spec[160];
    std::snprintf(child_spec, sizeof child_spec, "raster %d %d %.17g %.17g %.17g", p.width, p.height, render_sigma_,
                  chroma_sigma_, chroma_weight_);
    cl::Program& prog =
        rt_.program({"flatten.cl", "stroke.cl", "lines.cl", "raster.cl", "loss.cl",
                     "raster_backward.cl", "stroke_backward.cl"},
                    kernel_build_options(tuning) + loss_blur_options(render_sigma_, chroma_sigma_, chroma_weight_) +
                        " -DLOSS_TILE=" + std::to_string(kLossTile),
                    child_spec);
    program_ = &prog;
    local_budget_ = tuning.local_budget;
    k_flatten_ = cl::Kernel(prog, "flatten");
    k_stroke_ = cl::Kernel(prog, "stroke");
    k_lines_ = cl::Kernel(prog, "gather_lines");
    k_bounds_ = cl::Kernel(prog, "chunk_bounds");
    k_raster_ = cl::Kernel(prog, "raster");

    std::vector<int> a, b;
    std::vector<float> f;
    for (const auto& s : p.strokes) {
      a.insert(a.end(), {s.first_vertex, s.vertex_count, s.first_out, s.closed});
      b.insert(b.end(), {s.cap, s.join_points, s.cap_points, s.join});
      f.insert(f.end(), {s.half_width, s.miter_limit});
    }
    std::vector<float> dcol;
    std::vector<int> drule, dchunks, dpaint;
    for (const auto& d : p.draws) {
      dcol.insert(dcol.end(), d.rgba, d.rgba + 4);
      drule.push_back(d.rule);
      dpaint.push_back(d.paint);
      dchunks.insert(dchunks.end(), {d.first_chunk, d.chunk_count});
    }
    cp_ = make(K * p.n_cp * 2 * sizeof(float));
    vert_cp_ = make(p.vert_cp.size() * sizeof(int), p.vert_cp.data());
    vert_w_ = make(p.vert_w.size() * sizeof(float), p.vert_w.data());
    vert_join_ = make(p.vert_join.size(), p.vert_join.data());
    sp_a_ = make(a.size() * sizeof(int), a.data());
    sp_b_ = make(b.size() * sizeof(int), b.data());
    sp_f_ = make(f.size() * sizeof(float), f.data());
    pts_ = make(K * p.n_pts * 2 * sizeof(float));
    line_ab_ = make(p.line_ab.size() * sizeof(int), p.line_ab.data());
    lines_ = make(K * p.n_lines * 4 * sizeof(float));
    draw_color_ = make(dcol.size() * sizeof(float), dcol.data());
    draw_rule_ = make(drule.size() * sizeof(int), drule.data());
    draw_chunks_ = make(dchunks.size() * sizeof(int), dchunks.data());
    draw_paint_ = make(dpaint.size() * sizeof(int), dpaint.data());
    paint_ = make(p.paint.size() * sizeof(float), p.paint.data());
    chunk_lines_ = make(p.chunk_lines.size() * sizeof(int), p.chunk_lines.data());
    bounds_ = make(K * (p.chunk_lines.size() / 2) * 4 * sizeof(float));
    chunk_snap_ = make(K * (p.chunk_lines.size() / 2) * sizeof(int));  // chunk_bounds' boundary flags
    const LossBlurArgs blur = loss_blur_args(render_sigma_, chroma_sigma_, chroma_weight_);
    loss_blur_ = make(sizeof blur, &blur);
    // The output buffers are made on first use: a render needs only the 8-bit one.

    // Arguments never change between batches: set them once.
    const int n_strokes = static_cast<int>(p.strokes.size());
    set_args(k_flatten_, cp_, vert_cp_, vert_w_, pts_, p.n_cp, p.n_flat, p.n_pts);
    set_args(k_stroke_, pts_, sp_a_, sp_b_, sp_f_, vert_join_, n_strokes, p.n_pts);
    set_args(k_lines_, pts_, line_ab_, lines_, p.n_pts, p.n_lines, p.browser_edges ? 1 : 0);
    const int n_draws = static_cast<int>(p.draws.size());
    const int n_chunks = static_cast<int>(p.chunk_lines.size() / 2);
    set_args(k_bounds_, lines_, chunk_lines_, bounds_, p.n_lines, n_chunks, chunk_snap_, p.width);
    set_args(k_raster_, lines_, draw_chunks_, chunk_lines_, draw_color_, draw_rule_, bounds_,
             cl::Local(static_cast<size_t>(band_h_) * (p.width + 2) * sizeof(float)),
             cl::Local(static_cast<size_t>(band_h_) * p.width * 4 * sizeof(float)));
    // Arguments 8..12 (outputs) are set by forward().
    k_raster_.setArg(13, p.n_lines);
    k_raster_.setArg(14, n_chunks);
    k_raster_.setArg(15, n_draws);
    k_raster_.setArg(16, p.width);
    k_raster_.setArg(17, p.height);
    k_raster_.setArg(18, draw_paint_);
    k_raster_.setArg(19, paint_);
    k_raster_.setArg(20, loss_blur_);
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL setup of the rasteriser failed on ") + rt_.info().name +
                ": " + e.what() + " " + cl_status_name(e.err()));
  }
}

void ClRaster::set_control_points(const std::vector<float>& cp) {
  const size_t want = static_cast<size_t>(frames_) * plan_.n_cp * 2;
  if (cp.size() != want)
    throw Error("internal: control point upload of " + std::to_string(cp.size()) +
                " floats, expected " + std::to_string(want));
  rt_.queue().enqueueWriteBuffer(cp_, CL_FALSE, 0, want * sizeof(float), cp.data());
  rt_.queue().finish();  // cp may be a temporary of the caller
}

void ClRaster::set_rest_pose() {
  std::vector<float> all;
  all.reserve(static_cast<size_t>(frames_) * plan_.rest_cp.size());
  for (int k = 0; k < frames_; ++k) all.insert(all.end(), plan_.rest_cp.begin(), plan_.rest_cp.end());
  set_control_points(all);
}

void ClRaster::set_active_frames(int n) {
  if (n < 1 || n > frames_)
    throw Error("internal: active frames " + std::to_string(n) + " outside 1.." + std::to_string(frames_));
  active_ = n;
}

void ClRaster::forward(Output output, const std::array<float, 4>& background) {
  const auto& p = plan_;
  const size_t K = static_cast<size_t>(active_);
  const size_t pixels = K * p.height * static_cast<size_t>(p.width);
  events_.clear();
  try {
    // Arguments 8..12: where the band results go (an unused output gets any valid buffer).
    // Every frame's, not the active ones': the loss passes bind it (make_loss_buffers) and may
    // activate more frames later.
    if (output != Output::Rgba8 && !image_())
      image_ = make(static_cast<size_t>(frames_) * p.height * p.width * 4 * sizeof(float));
    if (output == Output::Rgba8 && !rgba_()) rgba_ = make(pixels * 4);
    if (output == Output::Residual && !ext_x_())
      throw Error("internal: a residual forward pass needs targets (set_targets)");
    k_raster_.setArg(8, image_() ? image_ : rgba_);
    k_raster_.setArg(9, rgba_() ? rgba_ : image_);
    k_raster_.setArg(10, ext_x_() ? ext_x_ : (image_() ? image_ : rgba_));
    k_raster_.setArg(11, cl_float4{{background[0], background[1], background[2], background[3]}});
    k_raster_.setArg(12, static_cast<int>(output));

    enqueue_geometry();
    // One work-group per (band, frame); see raster.cl for how its work-items share the work.
    launch("raster", k_raster_, cl::NDRange(bands_ * group_, K), cl::NDRange(group_, 1));
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL rasteriser launch failed on ") + rt_.info().name + ": " +
                e.what() + " " + cl_status_name(e.err()));
  }
}

void ClRaster::enqueue_geometry() { enqueue_geometry(0, active_); }

void ClRaster::enqueue_geometry(int first, int count) {
  const auto& p = plan_;
  const size_t K = static_cast<size_t>(count);
  const size_t wg = 64;  // a multiple of every device's preferred work-group granularity
  // Each kernel reads its frame from get_global_id(1): the offset picks the frames.
  const cl::NDRange at = first ? cl::NDRange(0, first) : cl::NullRange;
  if (p.n_flat > 0) launch("flatten", k_flatten_, cl::NDRange(round_up(p.n_flat, wg), K), cl::NullRange, at);
  if (!p.strokes.empty())
    launch("stroke", k_stroke_, cl::NDRange(round_up(p.strokes.size(), 8), K), kStrokeGroup, at);
  if (p.n_lines > 0) launch("gather_lines", k_lines_, cl::NDRange(round_up(p.n_lines, wg), K), cl::NullRange, at);
  if (!p.chunk_lines.empty())
    launch("chunk_bounds", k_bounds_, cl::NDRange(round_up(p.chunk_lines.size() / 2, wg), K), cl::NullRange, at);
}

std::vector<float> ClRaster::render_frames(int first, int count, const std::array<float, 4>& background) {
  std::vector<float> out;
  cl::Buffer img;  // the chunk's own output, gone when this returns: image_ (every frame's) is not made
  render_into(first, count, background, img, out);
  return out;
}

void ClRaster::render_frames_into(int first, int count, const std::array<float, 4>& background, std::vector<float>& out) {
  const size_t bytes = static_cast<size_t>(count) * plan_.height * plan_.width * 4 * sizeof(float);
  if (render_image_() && render_image_.getInfo<CL_MEM_SIZE>() != bytes) {
    device_bytes_ -= render_image_.getInfo<CL_MEM_SIZE>();
    render_image_ = cl::Buffer();
  }
  const bool made = !render_image_();
  render_into(first, count, background, render_image_, out);
  if (made) device_bytes_ += bytes;
}

void ClRaster::render_into(int first, int count, const std::array<float, 4>& background, cl::Buffer& img,
                           std::vector<float>& out) {
  if (first < 0 || count < 1 || first + count > frames_)
    throw Error("internal: render_frames of frames " + std::to_string(first) + ".." +
                std::to_string(first + count - 1) + " outside 0.." + std::to_string(frames_ - 1));
  const auto& p = plan_;
  const size_t pixels = static_cast<size_t>(count) * p.height * p.width;
  out.resize(pixels * 4);
  events_.clear();
  try {
    if (!img()) img = cl::Buffer(rt_.context(), CL_MEM_READ_WRITE, out.size() * sizeof(float));
    k_raster_.setArg(8, img);
    k_raster_.setArg(9, img);
    k_raster_.setArg(10, img);
    k_raster_.setArg(11, cl_float4{{background[0], background[1], background[2], background[3]}});
    k_raster_.setArg(12, static_cast<int>(Output::Float));
    enqueue_geometry(first, count);
    // The raster kernel writes frame first + j at slot j (its work-group's index).
    launch("raster", k_raster_, cl::NDRange(bands_ * group_, count), cl::NDRange(group_, 1),
           first ? cl::NDRange(0, first) : cl::NullRange);
    rt_.queue().enqueueReadBuffer(img, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL rasteriser launch failed on ") + rt_.info().name + ": " +
                e.what() + " " + cl_status_name(e.err()));
  }
}

void ClRaster::launch(const char* name, cl::Kernel& k, const cl::NDRange& global,
                      const cl::NDRange& local_or_null, const cl::NDRange& offset) {
  const cl::NDRange local = local_or_null.dimensions() ? local_or_null : stable_local_size(global);
  if (!rt_.profiling()) {
    rt_.queue().enqueueNDRangeKernel(k, offset, global, local);
    return;
  }
  cl::Event e;
  rt_.queue().enqueueNDRangeKernel(k, offset, global, local, nullptr, &e);
  events_.emplace_back(name, e);
}

std::vector<std::pair<std::string, double>> ClRaster::kernel_times() const {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& [name, e] : events_) {
    const double ns = static_cast<double>(e.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                                          e.getProfilingInfo<CL_PROFILING_COMMAND_START>());
    out.emplace_back(name, ns * 1e-6);
  }
  return out;
}

void ClRaster::finish() { rt_.queue().finish(); }

std::vector<uint8_t> ClRaster::read_rgba8() {
  if (!rgba_()) throw Error("internal: read_rgba8 before an Rgba8 forward pass");
  std::vector<uint8_t> out(static_cast<size_t>(frames_) * plan_.height * plan_.width * 4);
  rt_.queue().enqueueReadBuffer(rgba_, CL_TRUE, 0, out.size(), out.data());
  return out;
}

std::vector<float> ClRaster::read_image() {
  if (!image_()) throw Error("internal: read_image before a Float forward pass");
  std::vector<float> out(static_cast<size_t>(frames_) * plan_.height * plan_.width * 4);
  rt_.queue().enqueueReadBuffer(image_, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  return out;
}

void ClRaster::release_image() {
  if (render_image_()) {
    rt_.queue().finish();
    device_bytes_ -= render_image_.getInfo<CL_MEM_SIZE>();
    render_image_ = cl::Buffer();
  }
  if (!image_()) return;
  rt_.queue().finish();  // nothing enqueued still writes it
  device_bytes_ -= image_.getInfo<CL_MEM_SIZE>();
  image_ = cl::Buffer();
}

std::vector<float> ClRaster::read_image_frame(int k) {
  if (!image_()) throw Error("internal: read_image_frame before a Float forward pass");
  if (k < 0 || k >= frames_) throw Error("internal: read_image_frame of frame " + std::to_string(k));
  std::vector<float> out(static_cast<size_t>(plan_.height) * plan_.width * 4);
  const size_t bytes = out.size() * sizeof(float);
  rt_.queue().enqueueReadBuffer(image_, CL_TRUE, static_cast<size_t>(k) * bytes, bytes, out.data());
  return out;
}

}  // namespace svgm
