// The CPU layer compositor (see layer_compositor.h).
#include "raster/layer_compositor.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "raster/area_coverage.h"
#include "raster/browser_stroke.h"
#include "raster/gradient_paint.h"
#include "raster/raster_plan.h"
#include "raster/raster_ref.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

// Masks of masks and clips of clips nest no deeper than this (the reader cuts cycles; this
// bounds pathological but acyclic chains).
constexpr int kMaxNesting = 16;

// Rec. 709 luminance coefficients, which the SVG and CSS Masking specs give for mask-type
// luminance (applied to the sRGB values, as resvg and browsers do).
constexpr float kLumR = 0.2125f, kLumG = 0.7154f, kLumB = 0.0721f;

using Image = std::vector<float>;  // premultiplied RGBA, height * width * 4

// The raster plan of a list of paths, drawn opaque so that every visible fill and stroke gets
// a draw (the plan skips transparent ones), and the points of its rest pose.
struct Planned {
  RasterPlan plan;
  std::vector<double> pts;
};

class Compositor {
 public:
  Compositor(const Scene& scene, const RenderSize& size, bool browser_edges)
      : scene_(scene), view_(size.view), w_(size.width), h_(size.height),
        browser_edges_(browser_edges) {}

  Image paths_image(const std::vector<Path>& paths, int depth) {
    Image root(pixels() * 4, 0.0f);
    const Planned p = plan(paths);
    struct Open {
      int layer;
      Image img;
    };
    std::vector<Open> stack;
    auto top = [&]() -> Image& { return stack.empty() ? root : stack.back().img; };
    auto pop = [&]() {
      Open o = std::move(stack.back());
      stack.pop_back();
      composite(o.img, scene_.layers[o.layer], top(), depth);
    };
    for (size_t di = 0; di < p.plan.draws.size(); ++di) {
      const Draw& d = p.plan.draws[di];
      const Path& path = paths[d.path];
      // The path's layers, outermost first.
      std::vector<int> chain;
      for (int l = path.layer; l >= 0; l = scene_.layers[l].parent) chain.push_back(l);
      std::reverse(chain.begin(), chain.end());
      size_t k = 0;
      while (k < stack.size() && k < chain.size() && stack[k].layer == chain[k]) ++k;
      while (stack.size() > k) pop();
      while (stack.size() < chain.size()) stack.push_back({chain[stack.size()], Image(pixels() * 4, 0.0f)});
      // Under browser edges a hairline-wide stroke is drawn as the browser's hairline instead.
      if (browser_edges_ && d.is_stroke && browser_hairline(path, view_))
        paint(top(), path, true, Coverage{0, 0, w_, h_, browser_hairline_coverage(path, view_, w_, h_)});
      else
        paint(top(), path, d.is_stroke, draw_coverage_box(p.plan, p.pts, static_cast<int>(di)));
    }
    while (!stack.empty()) pop();
    return root;
  }

 private:
  size_t pixels() const { return static_cast<size_t>(w_) * h_; }

  Planned plan(const std::vector<Path>& paths) const {
    Scene opaque;
    opaque.width = scene_.width;
    opaque.height = scene_.height;
    opaque.paths = paths;
    for (Path& q : opaque.paths) {
      q.fill.a = 1;
      q.stroke.color.a = 1;
      q.opacity = 1;
    }
    // Coverage only: this compositor paints gradients itself (paint()), so no paint images.
    RasterPlanOptions coverage_only;
    coverage_only.max_paint_bytes = 0;
    Planned p{plan_raster(opaque, view_, w_, h_, coverage_only), {}};
    const std::vector<double> cp(p.plan.rest_cp.begin(), p.plan.rest_cp.end());
    p.pts = ref::flatten(p.plan, cp);
    ref::stroke(p.plan, p.pts);
    if (browser_edges_)  // every line's end points are points of pts: snapping them snaps edges
      for (size_t i = 1; i < p.pts.size(); i += 2) p.pts[i] = browser_edge_y(p.pts[i]);
    return p;
  }

  // Source-over of one fill or stroke with its paint, weighted by coverage.
  void paint(Image& dst, const Path& path, bool stroke, const Coverage& cov) const {
    const int gi = stroke ? path.stroke_gradient : path.fill_gradient;
    const Rgba flat = stroke ? path.stroke.color : path.fill;
    const Gradient* g = gi >= 0 ? &scene_.gradients[gi] : nullptr;
    const Affine to_gradient = g ? (view_ * g->to_canvas).inverse() : Affine{};
    const float k = path.local_opacity * (g ? g->opacity : 1.0f);
    for (int y = cov.y0; y < cov.y0 + cov.h; ++y)
      for (int x = cov.x0; x < cov.x0 + cov.w; ++x) {
        const size_t i = static_cast<size_t>(y) * w_ + x;
        const float cv = cov.a[static_cast<size_t>(y - cov.y0) * cov.w + (x - cov.x0)];
        if (cv <= 0) continue;
        Rgba c = flat;
        if (g) {
          const auto gc = gradient_color(*g, to_gradient, {x + 0.5, y + 0.5});
          if (!gc) continue;
          c = *gc;
        }
        const float a = cv * c.a * k;
        float* o = dst.data() + 4 * i;
        o[0] = c.r * a + o[0] * (1 - a);
        o[1] = c.g * a + o[1] * (1 - a);
        o[2] = c.b * a + o[2] * (1 - a);
        o[3] = a + o[3] * (1 - a);
      }
  }

  // A finished layer into the one below it, times opacity, clip coverage and mask value.
  void composite(const Image& src, const Layer& layer, Image& dst, int depth) {
    std::vector<float> m(pixels(), layer.opacity);
    if (layer.clip >= 0) multiply(m, clip_coverage(layer.clip, depth + 1));
    if (layer.mask >= 0) multiply(m, mask_coverage(layer.mask, depth + 1));
    for (size_t i = 0; i < pixels(); ++i) {
      if (m[i] <= 0) continue;
      const float* s = src.data() + 4 * i;
      float* o = dst.data() + 4 * i;
      const float sa = s[3] * m[i];
      for (int c = 0; c < 3; ++c) o[c] = s[c] * m[i] + o[c] * (1 - sa);
      o[3] = sa + o[3] * (1 - sa);
    }
  }

  static void multiply(std::vector<float>& m, const std::vector<float>& by) {
    for (size_t i = 0; i < m.size(); ++i) m[i] *= by[i];
  }

  void check_depth(int depth) const {
    if (depth > kMaxNesting)
      throw Error("clip paths or masks nested deeper than " + std::to_string(kMaxNesting));
  }

  // The union of a clip's shapes (each drawn as the others' complement would be: 1 − Π(1 − c)),
  // times its own clip-path.
  std::vector<float> clip_coverage(int index, int depth) {
    check_depth(depth);
    const ClipPath& clip = scene_.clips[index];
    std::vector<float> out(pixels(), 0.0f);
    const Planned p = plan(clip.paths);
    for (size_t di = 0; di < p.plan.draws.size(); ++di) {
      if (p.plan.draws[di].is_stroke) continue;
      const std::vector<float> c = draw_coverage(p.plan, p.pts, static_cast<int>(di));
      for (size_t i = 0; i < out.size(); ++i) out[i] = out[i] + c[i] - out[i] * c[i];
    }
    if (clip.clip >= 0) multiply(out, clip_coverage(clip.clip, depth + 1));
    return out;
  }

  // Luminance times alpha (or alpha) of the mask's content, inside its region, times its own mask.
  std::vector<float> mask_coverage(int index, int depth) {
    check_depth(depth);
    const Mask& mask = scene_.masks[index];
    const Image content = paths_image(mask.paths, depth);
    std::vector<float> out(pixels(), 0.0f);
    for (size_t i = 0; i < out.size(); ++i) {
      const float* c = content.data() + 4 * i;  // premultiplied: luminance already times alpha
      out[i] = mask.luminance ? kLumR * c[0] + kLumG * c[1] + kLumB * c[2] : c[3];
    }
    Path region;
    region.subpaths = mask.region;
    region.has_fill = true;
    region.has_stroke = false;
    const Planned p = plan({region});
    if (p.plan.draws.empty()) return std::vector<float>(pixels(), 0.0f);
    multiply(out, draw_coverage(p.plan, p.pts, 0));
    if (mask.mask >= 0) multiply(out, mask_coverage(mask.mask, depth + 1));
    return out;
  }

  const Scene& scene_;
  Affine view_;
  int w_, h_;
  bool browser_edges_;  // RasterPlan::browser_edges for every plan it makes
};

}  // namespace

std::vector<float> composite_layers(const Scene& scene, const RenderSize& size, bool browser_edges) {
  return Compositor(scene, size, browser_edges).paths_image(scene.paths, 0);
}

RgbaImage render_layers(const Scene& scene, const RenderSize& size, bool transparent,
                        bool browser_edges) {
  const std::vector<float> img = composite_layers(scene, size, browser_edges);
  RgbaImage out{size.width, size.height, std::vector<uint8_t>(img.size())};
  const float bg = transparent ? 0.0f : 1.0f;
  auto byte = [](float v) { return static_cast<uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
  for (size_t i = 0; i < img.size(); i += 4) {
    float c[4];
    for (int k = 0; k < 4; ++k) c[k] = img[i + k] + bg * (1 - img[i + 3]);
    const float a = c[3];
    for (int k = 0; k < 3; ++k) out.rgba[i + k] = byte(a > 0 ? c[k] / a : 0.0f);
    out.rgba[i + 3] = byte(a);
  }
  return out;
}

}  // namespace svgm
