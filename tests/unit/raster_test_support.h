// Test-only: render a scene through the OpenCL rasteriser and the CPU reference.
#pragma once

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

}  // namespace svgm::test
