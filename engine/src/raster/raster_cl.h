// The OpenCL forward rasteriser: one host routine that executes a RasterPlan for K frames.
//
// Per batch: flatten (F = B P) -> stroke (outline points) -> gather_lines -> chunk_bounds ->
// raster (coverage + compositing per band of rows). All buffers stay on the device; the host enqueues
// the five launches on an in-order queue and only reads back what is asked for.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "opencl/runtime.h"
#include "raster/raster_plan.h"

namespace svgm {

class ClRaster {
 public:
  ClRaster(ClRuntime& rt, const RasterPlan& plan, int frames);

  int frames() const { return frames_; }
  const RasterPlan& plan() const { return plan_; }

  // Uploads control points for all frames: frames * n_cp (x, y) pairs.
  void set_control_points(const std::vector<float>& cp);
  // Uploads the plan's rest pose into every frame.
  void set_rest_pose();

  enum class Output { Float, Rgba8 };
  // Enqueues the forward pass; returns at once (the queue is in order). Float keeps
  // premultiplied float RGBA images (read_image); Rgba8 writes 8-bit straight RGBA over
  // `background`, premultiplied ({1,1,1,1} white, {0,0,0,0} transparent) (read_rgba8).
  void forward(Output output = Output::Float, const std::array<float, 4>& background = {});
  // Blocks until the queue is idle.
  void finish();

  // Reads the 8-bit images of the last Rgba8 forward: frames * height * width * 4 bytes.
  std::vector<uint8_t> read_rgba8();
  // Reads the premultiplied float RGBA images: frames * height * width * 4 floats.
  std::vector<float> read_image();

  // With a profiling runtime: milliseconds each kernel of the last forward() took on the device.
  std::vector<std::pair<std::string, double>> kernel_times() const;

  // Bytes of device memory this routine allocated.
  size_t device_bytes() const { return device_bytes_; }

 private:
  cl::Buffer make(size_t bytes, const void* host = nullptr);
  void launch(const char* name, cl::Kernel& k, const cl::NDRange& global,
              const cl::NDRange& local = cl::NullRange);

  ClRuntime& rt_;
  RasterPlan plan_;
  int frames_;
  int band_h_ = 16, bands_ = 0, group_ = 1;
  size_t device_bytes_ = 0;
  std::vector<std::pair<std::string, cl::Event>> events_;
  cl::Kernel k_flatten_, k_stroke_, k_lines_, k_bounds_, k_raster_;
  cl::Buffer cp_, vert_cp_, vert_w_, vert_join_, sp_a_, sp_b_, sp_f_, pts_, line_ab_, lines_,
      draw_chunks_, chunk_lines_, draw_color_, draw_rule_, bounds_, acc_, image_, rgba_;
};

}  // namespace svgm
