// The OpenCL forward rasteriser routine (see raster_cl.h and kernels/*.cl for the maths).
#include "raster/raster_cl.h"

#include <algorithm>

#include "opencl/tuning.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

size_t round_up(size_t n, size_t m) { return (n + m - 1) / m * m; }

}  // namespace

cl::Buffer ClRaster::make(size_t bytes, const void* host) {
  bytes = std::max<size_t>(bytes, 16);  // OpenCL refuses zero-sized buffers
  device_bytes_ += bytes;
  if (host)
    return cl::Buffer(rt_.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes,
                      const_cast<void*>(host));
  return cl::Buffer(rt_.context(), CL_MEM_READ_WRITE, bytes);
}

ClRaster::ClRaster(ClRuntime& rt, const RasterPlan& plan, int frames)
    : rt_(rt), plan_(plan), frames_(frames) {
  if (frames < 1) throw Error("frame count must be at least 1");
  const auto& p = plan_;
  const size_t K = static_cast<size_t>(frames);
  try {
    cl::Program& prog = rt_.program({"flatten.cl", "stroke.cl", "lines.cl", "bin.cl", "raster.cl"},
                                    kernel_build_options(rt_.info()));
    k_flatten_ = cl::Kernel(prog, "flatten");
    k_stroke_ = cl::Kernel(prog, "stroke");
    k_lines_ = cl::Kernel(prog, "gather_lines");
    k_bin_ = cl::Kernel(prog, "bin_lines");
    k_raster_ = cl::Kernel(prog, "raster");
    k_rgba8_ = cl::Kernel(prog, "to_rgba8");

    std::vector<int> a, b;
    std::vector<float> f;
    for (const auto& s : p.strokes) {
      a.insert(a.end(), {s.first_vertex, s.vertex_count, s.first_out, s.closed});
      b.insert(b.end(), {s.cap, s.join_points, s.cap_points, s.join});
      f.insert(f.end(), {s.half_width, s.miter_limit});
    }
    std::vector<float> dcol;
    std::vector<int> drule;
    for (const auto& d : p.draws) {
      dcol.insert(dcol.end(), d.rgba, d.rgba + 4);
      drule.push_back(d.rule);
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
    line_draw_ = make(p.line_draw.size() * sizeof(int), p.line_draw.data());
    draw_color_ = make(dcol.size() * sizeof(float), dcol.data());
    draw_rule_ = make(drule.size() * sizeof(int), drule.data());
    bins_ = make(K * p.bands * static_cast<size_t>(p.n_lines) * sizeof(int));
    bin_count_ = make(K * p.bands * sizeof(int));
    acc_ = make(K * p.height * static_cast<size_t>(p.width + 2) * sizeof(float));
    image_ = make(K * p.height * static_cast<size_t>(p.width) * 4 * sizeof(float));
    rgba_ = make(K * p.height * static_cast<size_t>(p.width) * 4);
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

void ClRaster::forward() {
  const auto& p = plan_;
  auto& q = rt_.queue();
  const size_t K = static_cast<size_t>(frames_);
  const size_t wg = 64;
  try {
    if (p.n_flat > 0) {
      k_flatten_.setArg(0, cp_); k_flatten_.setArg(1, vert_cp_); k_flatten_.setArg(2, vert_w_);
      k_flatten_.setArg(3, pts_); k_flatten_.setArg(4, p.n_cp); k_flatten_.setArg(5, p.n_flat);
      k_flatten_.setArg(6, p.n_pts);
      q.enqueueNDRangeKernel(k_flatten_, cl::NullRange, cl::NDRange(round_up(p.n_flat, wg), K),
                             cl::NullRange);
    }
    if (!p.strokes.empty()) {
      const int n = static_cast<int>(p.strokes.size());
      k_stroke_.setArg(0, pts_); k_stroke_.setArg(1, sp_a_); k_stroke_.setArg(2, sp_b_);
      k_stroke_.setArg(3, sp_f_); k_stroke_.setArg(4, vert_join_); k_stroke_.setArg(5, n);
      k_stroke_.setArg(6, p.n_pts);
      q.enqueueNDRangeKernel(k_stroke_, cl::NullRange, cl::NDRange(round_up(n, 8), K),
                             cl::NullRange);
    }
    if (p.n_lines > 0) {
      k_lines_.setArg(0, pts_); k_lines_.setArg(1, line_ab_); k_lines_.setArg(2, lines_);
      k_lines_.setArg(3, p.n_pts); k_lines_.setArg(4, p.n_lines);
      q.enqueueNDRangeKernel(k_lines_, cl::NullRange, cl::NDRange(round_up(p.n_lines, wg), K),
                             cl::NullRange);
    }
    k_bin_.setArg(0, lines_); k_bin_.setArg(1, bins_); k_bin_.setArg(2, bin_count_);
    k_bin_.setArg(3, p.n_lines); k_bin_.setArg(4, p.bands); k_bin_.setArg(5, p.width);
    q.enqueueNDRangeKernel(k_bin_, cl::NullRange, cl::NDRange(round_up(p.bands, 8), K),
                           cl::NullRange);
    k_raster_.setArg(0, lines_); k_raster_.setArg(1, line_draw_); k_raster_.setArg(2, draw_color_);
    k_raster_.setArg(3, draw_rule_); k_raster_.setArg(4, bins_); k_raster_.setArg(5, bin_count_);
    k_raster_.setArg(6, acc_); k_raster_.setArg(7, image_); k_raster_.setArg(8, p.n_lines);
    k_raster_.setArg(9, p.bands); k_raster_.setArg(10, p.width); k_raster_.setArg(11, p.height);
    q.enqueueNDRangeKernel(k_raster_, cl::NullRange,
                           cl::NDRange(round_up(p.height, kBandHeight), K),
                           cl::NDRange(kBandHeight, 1));
  } catch (const cl::Error& e) {
    throw Error(std::string("OpenCL rasteriser launch failed on ") + rt_.info().name + ": " +
                e.what() + " " + cl_status_name(e.err()));
  }
}

void ClRaster::finish() { rt_.queue().finish(); }

std::vector<uint8_t> ClRaster::read_rgba8(const float background[4]) {
  const size_t n = static_cast<size_t>(frames_) * plan_.height * plan_.width;
  std::vector<uint8_t> out(n * 4);
  k_rgba8_.setArg(0, image_);
  k_rgba8_.setArg(1, rgba_);
  k_rgba8_.setArg(2, cl_float4{{background[0], background[1], background[2], background[3]}});
  k_rgba8_.setArg(3, static_cast<int>(n));
  rt_.queue().enqueueNDRangeKernel(k_rgba8_, cl::NullRange, cl::NDRange(round_up(n, 256)),
                                   cl::NullRange);
  rt_.queue().enqueueReadBuffer(rgba_, CL_TRUE, 0, out.size(), out.data());
  return out;
}

std::vector<float> ClRaster::read_image() {
  std::vector<float> out(static_cast<size_t>(frames_) * plan_.height * plan_.width * 4);
  rt_.queue().enqueueReadBuffer(image_, CL_TRUE, 0, out.size() * sizeof(float), out.data());
  return out;
}

}  // namespace svgm
