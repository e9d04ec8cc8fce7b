// Test-only: the known-motion target generator. Moves the groups of a scene we drew by known
// homographies (the fitter's own motion model) plus a smooth bend, renders every keyframe with
// our renderer into a folder of PNG frames, so the fitter can be run on it exactly as a user's
// target and its result compared with the truth.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include "fit/fit_plan.h"
#include "fit/motion_model.h"
#include "raster_test_support.h"
#include "svgmotion/png_io.h"
#include "svgmotion/render_size.h"

namespace svgm::test {

// motion(k, g) gives group g's parameters at keyframe k; bend(k, p) an extra displacement (px)
// of a point p (pixels, after the group motion). Writes frames 000.png ... into `dir` and
// returns the control points of every keyframe (pixels, raster-plan layout).
inline std::vector<std::vector<double>> write_known_motion(
    const Scene& scene, int width, int K, const std::function<MotionParams(int, int)>& motion,
    const std::function<Vec2(int, Vec2)>& bend, const std::filesystem::path& dir) {
  const RenderSize size = render_size(scene, width);
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  const FitPlan fplan = plan_fit(scene, plan, {});
  const Vec2 origin{0.5 * size.width, 0.5 * size.height};
  const double scale = 0.5 * size.width;
  std::filesystem::create_directories(dir);
  std::vector<std::vector<double>> truth;
  ClRaster r(runtime(), plan, 1);
  for (int k = 0; k < K; ++k) {
    std::vector<double> cp(plan.rest_cp.size(), 0.0);
    std::vector<float> cpf(plan.rest_cp.size(), 0.f);
    for (int i = 0; i < plan.n_cp; ++i) {
      if (fplan.cp_group[i] < 0) continue;
      const Vec2 rest{plan.rest_cp[2 * i], plan.rest_cp[2 * i + 1]};
      Vec2 q = apply_motion(motion(k, fplan.cp_group[i]), rest, origin, scale);
      q = q + bend(k, q);
      cp[2 * i] = q.x;
      cp[2 * i + 1] = q.y;
      cpf[2 * i] = static_cast<float>(q.x);
      cpf[2 * i + 1] = static_cast<float>(q.y);
    }
    truth.push_back(cp);
    r.set_control_points(cpf);
    r.forward(ClRaster::Output::Rgba8, {1, 1, 1, 1});
    RgbaImage img{size.width, size.height, r.read_rgba8()};
    char name[32];
    std::snprintf(name, sizeof name, "%03d.png", k);
    write_png(dir / name, img);
  }
  return truth;
}

// PSNR (dB) of two RGB(A) float images in [0, 1] (alpha ignored) and the IoU of their
// foregrounds (darkest channel < 0.9), as ../shared/tools/fitcheck.py measures them.
struct ImageAgreement {
  double psnr = 0, iou = 0;
};

inline ImageAgreement agreement(const float* a, const float* b, size_t pixels) {
  double se = 0;
  size_t inter = 0, uni = 0;
  for (size_t p = 0; p < pixels; ++p) {
    float ma = 1, mb = 1;
    for (int c = 0; c < 3; ++c) {
      const double d = a[4 * p + c] - b[4 * p + c];
      se += d * d;
      ma = std::min(ma, a[4 * p + c]);
      mb = std::min(mb, b[4 * p + c]);
    }
    inter += (ma < 0.9f) && (mb < 0.9f);
    uni += (ma < 0.9f) || (mb < 0.9f);
  }
  const double mse = se / (3.0 * pixels);
  return {mse == 0 ? 99.0 : 10 * std::log10(1.0 / mse), uni ? double(inter) / uni : 1.0};
}

}  // namespace svgm::test
