// Test-only: the known-motion target generator. Moves the groups of a scene we drew by known
// homographies (the fitter's own motion model) plus a smooth bend and draws every keyframe into
// a folder of PNG frames with the independent rasteriser of supersampled_fill.h (not the
// engine's renderer, so a bug shared by renderer and fitter cannot make the fit look right),
// so the fitter can be run on it exactly as on a user's target and its result compared with
// the truth.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <vector>

#include "fit/plan/fit_plan.h"
#include "fit/optimise/motion_model.h"
#include "raster/raster_plan.h"
#include "supersampled_fill.h"
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
  // Where group g's point p (pixels, at rest) is at keyframe k.
  auto moved = [&](int k, int g, Vec2 p) {
    const Vec2 q = apply_motion(motion(k, g), p, origin, scale);
    return q + bend(k, q);
  };
  std::filesystem::create_directories(dir);
  std::vector<std::vector<double>> truth;
  for (int k = 0; k < K; ++k) {
    // The truth in the fitter's layout (its control points); padding stays at 0.
    std::vector<double> cp(plan.rest_cp.size(), 0.0);
    for (int i = 0; i < plan.n_cp; ++i) {
      if (fplan.cp_group[i] < 0) continue;
      const Vec2 q = moved(k, fplan.cp_group[i], {plan.rest_cp[2 * i], plan.rest_cp[2 * i + 1]});
      cp[2 * i] = q.x;
      cp[2 * i + 1] = q.y;
    }
    truth.push_back(cp);
    // The image from the scene's own paths, moved the same way, drawn independently.
    const auto outlines = filled_outlines(scene, [&](size_t path, Vec2 p) {
      const int g = scene.paths[path].group;
      if (g < 0) throw std::logic_error("write_known_motion: every path needs a group");
      return moved(k, g, size.view.apply(p));
    });
    char name[32];
    std::snprintf(name, sizeof name, "%03d.png", k);
    write_png(dir / name, draw_over_white(outlines, size.width, size.height));
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
