// The OpenCL forward rasteriser: one host routine that executes a RasterPlan for K frames.
//
// Per batch: flatten (F = B P) -> stroke (outline points) -> gather_lines -> bin_lines ->
// raster (coverage + compositing per row). All buffers stay on the device; the host enqueues
// the five launches on an in-order queue and only reads back what is asked for.
#pragma once

#include <cstdint>
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

  // Enqueues the forward pass; returns at once (the queue is in order).
  void forward();
  // Blocks until the queue is idle.
  void finish();

  // Reads frame images as 8-bit straight RGBA over the given premultiplied background
  // ({1,1,1,1} white, {0,0,0,0} transparent): frames * height * width * 4 bytes.
  std::vector<uint8_t> read_rgba8(const float background[4]);
  // Reads the premultiplied float RGBA images: frames * height * width * 4 floats.
  std::vector<float> read_image();

  // Bytes of device memory this routine allocated.
  size_t device_bytes() const { return device_bytes_; }

 private:
  cl::Buffer make(size_t bytes, const void* host = nullptr);

  ClRuntime& rt_;
  RasterPlan plan_;
  int frames_;
  size_t device_bytes_ = 0;
  cl::Kernel k_flatten_, k_stroke_, k_lines_, k_bin_, k_raster_, k_rgba8_;
  cl::Buffer cp_, vert_cp_, vert_w_, vert_join_, sp_a_, sp_b_, sp_f_, pts_, line_ab_, lines_,
      line_draw_, draw_color_, draw_rule_, bins_, bin_count_, acc_, image_, rgba_;
};

}  // namespace svgm
