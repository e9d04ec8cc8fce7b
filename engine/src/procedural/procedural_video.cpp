// Procedural candidate videos (see procedural_video.h).
#include "procedural/procedural_video.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <random>

#include "media/preview_video.h"
#include "opencl/runtime.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "svgmotion/error.h"
#include "svgmotion/render_size.h"

namespace svgm {

void write_procedural_video(const Scene& scene, const std::vector<Vec2>& pts, uint32_t seed,
                            const ProceduralVideoOptions& o, const std::filesystem::path& out) {
  if (o.frames < 2) throw Error("procedural video: frames must be at least 2");
  const RenderSize size = render_size(scene, o.width);
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  const size_t per_frame = pts.size() / o.frames;
  if (pts.size() % o.frames != 0 || per_frame + 3 != static_cast<size_t>(plan.n_cp))
    throw Error("internal: procedural motion and raster plan disagree on the points");
  std::vector<float> cp;
  cp.reserve(static_cast<size_t>(o.frames) * plan.n_cp * 2);
  for (int f = 0; f < o.frames; ++f) {
    for (size_t i = 0; i < per_frame; ++i) {
      const Vec2 q = size.view.apply(pts[f * per_frame + i]);
      cp.push_back(static_cast<float>(q.x));
      cp.push_back(static_cast<float>(q.y));
    }
    cp.insert(cp.end(), 6, 0.f);  // the plan's padding points
  }
  ClRuntime rt(o.device);
  ClRaster r(rt, plan, o.frames);
  r.set_control_points(cp);
  // Degradations: each channel drifts linearly (direction by the seed), then a slight blur;
  // the encoder adds the compression.
  std::mt19937 rng(seed * 2654435761u + 1);
  std::uniform_real_distribution<double> U(-1, 1);
  const double dir[3] = {U(rng), U(rng), U(rng)};
  const int W = size.width, H = size.height;
  // One frame rendered at a time, as the encoder asks for it (the same bits as its part of a
  // render of every frame): all 49 frames at once were 16 bytes per pixel and frame on the
  // device and again on the host, 410 MB at 512 px, the bundled example's peak once the fit's
  // memory was cut (issue 38). The frame's images are made once and reused (render_frames_into).
  std::vector<float> img;
  cv::Mat m(H, W, CV_32FC4), blurred;  // GaussianBlur makes `blurred` once, then reuses it
  write_preview_video(out, o.frames, 1, [&](int f, int) {
    const double t = static_cast<double>(f) / (o.frames - 1);
    r.render_frames_into(f, 1, {1, 1, 1, 1}, img);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const float* c = &img[(static_cast<size_t>(y) * W + x) * 4];
        cv::Vec4f v;
        for (int ch = 0; ch < 3; ++ch)
          v[ch] = static_cast<float>(std::clamp((c[ch] + 1 - c[3]) * (1 + o.drift * t * dir[ch]), 0.0, 1.0));
        v[3] = 1;
        m.at<cv::Vec4f>(y, x) = v;
      }
    if (o.blur_sigma <= 0) return rgba8_image(reinterpret_cast<const float*>(m.data), W, H);
    cv::GaussianBlur(m, blurred, cv::Size(0, 0), o.blur_sigma);
    return rgba8_image(reinterpret_cast<const float*>(blurred.data), W, H);
  }, o.fps);
}

}  // namespace svgm
