// Test-only: render a scene through the OpenCL rasteriser and the CPU reference.
#pragma once

#include <cstring>
#include <random>
#include <vector>

#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "raster/raster_ref.h"
#include "svgmotion/scene.h"

namespace svgm::test {

inline ClRuntime& runtime() {
  static ClRuntime rt("auto");
  return rt;
}

// Premultiplied float RGBA of `frames` copies of the scene at its own size (identity view).
inline std::vector<float> render_cl(const Scene& scene, int frames = 1, RasterPlanOptions opt = {}) {
  const RasterPlan plan = plan_raster(scene, Affine{}, static_cast<int>(scene.width),
                                      static_cast<int>(scene.height), opt);
  ClRaster r(runtime(), plan, frames);
  r.set_rest_pose();
  r.forward();
  return r.read_image();
}

inline std::vector<double> render_ref(const Scene& scene, RasterPlanOptions opt = {}) {
  const RasterPlan plan = plan_raster(scene, Affine{}, static_cast<int>(scene.width),
                                      static_cast<int>(scene.height), opt);
  return ref::render(plan, std::vector<double>(plan.rest_cp.begin(), plan.rest_cp.end()));
}

template <class V>
double alpha_sum(const V& img) {
  double s = 0;
  for (size_t i = 3; i < img.size(); i += 4) s += img[i];
  return s;
}

// `frames` copies of the rest pose, frame k shifted by (dx (k + 1), dy): control points for
// a plan's frames, and (through targets_on_white) targets a known shift away.
inline std::vector<float> shifted_cp(const RasterPlan& plan, int frames, float dx, float dy) {
  std::vector<float> cp;
  for (int k = 0; k < frames; ++k)
    for (size_t i = 0; i < plan.rest_cp.size(); i += 2) {
      cp.push_back(static_cast<float>(plan.rest_cp[i]) + dx * static_cast<float>(k + 1));
      cp.push_back(static_cast<float>(plan.rest_cp[i + 1]) + dy);
    }
  return cp;
}

// The plan's scene at shifted_cp(plan, frames, dx, dy), composited on white (straight RGB,
// A = 1): what a target video of that motion holds.
inline std::vector<float> targets_on_white(const RasterPlan& plan, int frames, float dx, float dy) {
  ClRaster r(runtime(), plan, frames);
  r.set_control_points(shifted_cp(plan, frames, dx, dy));
  r.set_active_frames(frames);
  r.forward();
  std::vector<float> img = r.read_image();
  for (size_t p = 0; p < img.size(); p += 4) {
    for (int c = 0; c < 3; ++c) img[p + c] += 1 - img[p + 3];
    img[p + 3] = 1;
  }
  return img;
}

// A frame and a target perturbed from the plan's rest pose (seeded normal offsets, sd 0.7 px and
// twice that; the 3 padding points stay at 0): `cp` the frame's control points, `target` the
// target's render by the CPU reference composited on white, as targets are.
struct PerturbedPair {
  std::vector<double> cp;
  std::vector<float> target;
};
inline PerturbedPair perturbed_pair(const RasterPlan& plan, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0, 0.7);
  PerturbedPair out{std::vector<double>(plan.rest_cp.begin(), plan.rest_cp.end()), {}};
  std::vector<double> target_cp = out.cp;
  const size_t n = static_cast<size_t>(plan.n_cp - 3) * 2;
  for (size_t i = 0; i < n; ++i) {
    out.cp[i] += N(rng);
    target_cp[i] += 2 * N(rng);
  }
  const std::vector<double> t = ref::render(plan, target_cp);
  for (size_t p = 0; p < t.size() / 4; ++p) {
    for (int ch = 0; ch < 3; ++ch) out.target.push_back(static_cast<float>(t[4 * p + ch] + 1.0 - t[4 * p + 3]));
    out.target.push_back(1.f);
  }
  return out;
}

inline bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace svgm::test
