// The kernels of one program compiled by launching them (see warm_kernels.h).
#include "cli/warm_kernels.h"

#include <array>
#include <sstream>
#include <vector>

#include "fit/optimise/fitter.h"
#include "fit/target/distance_field.h"
#include "raster/raster_cl.h"
#include "raster/raster_plan.h"
#include "scene/synthetic_scene.h"
#include "svgmotion/error.h"
#include "svgmotion/render_size.h"

namespace svgm::cli {

namespace {

constexpr std::array<float, 4> kWhite{1, 1, 1, 1};

// Blobs with one of them stroked too: a plan with fills, strokes and lines, so that every
// kernel of the raster program has work.
Scene warm_scene(double size) {
  Scene s = synthetic_blobs(3, size, 1);
  s.paths[0].has_stroke = true;
  s.paths[0].stroke.color = {0.1f, 0.2f, 0.3f, 1.0f};
  s.paths[0].stroke.width = size / 100;
  return s;
}

}  // namespace

void warm_raster(ClRuntime& rt, int width, int height, double sigma, double chroma_sigma, double chroma_weight) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384) throw Error("warm-for: bad raster size");
  const Scene scene = warm_scene(width);
  const RasterPlan plan =
      plan_raster(scene, Affine::scale(1.0, static_cast<double>(height) / width), width, height);
  ClRaster r(rt, plan, 2, sigma, chroma_sigma, chroma_weight);
  r.set_rest_pose();
  r.forward(ClRaster::Output::Rgba8, kWhite);
  r.forward(ClRaster::Output::Float, kWhite);
  const std::vector<float> target = r.read_image();  // set_targets keeps no copy
  r.release_image();
  // Frames drawn one at a time (the procedural candidates, the final renders): the offset
  // launches, the first frame's zero offset and the second's not.
  std::vector<float> frame;
  r.render_frames_into(0, 1, kWhite, frame);
  r.render_frames_into(1, 1, kWhite, frame);
  r.release_image();
  // The loss a frame at a time: its kernels at offset 0 and 1.
  r.set_targets(target);
  r.set_loss_chunk_frames(1);
  r.loss_and_gradient(1000.0f, kWhite);
  r.read_cp_gradient();
  r.finish();
}

void warm_fitter(ClRuntime& rt) {
  const int width = 256;
  const Scene scene = warm_scene(width);
  const RenderSize size = render_size(scene, width);
  const int K = 2;
  const size_t px = static_cast<size_t>(size.width) * size.height;
  // The target: the drawing at rest in both keyframes.
  const RasterPlan plan = plan_raster(scene, size.view, size.width, size.height);
  std::vector<float> rest;
  {
    ClRaster r(rt, plan, 1);
    r.set_rest_pose();
    r.forward(ClRaster::Output::Float, kWhite);
    rest = r.read_image();
  }
  TargetFrames t;
  t.width = size.width;
  t.height = size.height;
  t.keyframes = K;
  t.source_frames = K;
  t.source_width = size.width;
  t.source_height = size.height;
  t.source_index = {0, 1};
  t.rgba.resize(K * px * 4);
  t.mask.resize(K * px);
  for (int k = 0; k < K; ++k)
    for (size_t i = 0; i < px; ++i) {
      float* o = &t.rgba[(k * px + i) * 4];
      bool ink = false;
      for (int c = 0; c < 3; ++c) {
        o[c] = rest[i * 4 + c] + (1 - rest[i * 4 + 3]);  // premultiplied over white, straight
        ink = ink || o[c] < 0.97f;
      }
      o[3] = 1;
      t.mask[k * px + i] = ink;
    }
  fill_distance_fields(t);
  // Every kernel of the fitter's program: the field, free offsets, cohesion and G1 joints.
  FitOptions fo;
  fo.iterations = 3;
  fo.pin_rest_keyframe = false;
  fo.lr_offsets = 0.05f;
  fo.w_cohesion = 1;
  fo.track = false;
  Fitter f(rt, scene, t, fo);
  while (!f.done()) f.step();
  rt.queue().finish();
}

void warm_for(ClRuntime& rt, const std::string& spec) {
  std::istringstream in(spec);
  std::string what;
  in >> what;
  if (what == "fitter") return warm_fitter(rt);
  int w = 0, h = 0;
  double sigma = 0, chroma_sigma = 0, chroma_weight = 0;
  if (what == "raster" && (in >> w >> h >> sigma >> chroma_sigma >> chroma_weight))
    return warm_raster(rt, w, h, sigma, chroma_sigma, chroma_weight);
  throw Error("devices --warm-for: unknown program '" + spec + "'");
}

}  // namespace svgm::cli
