// The scene model: what an SVG becomes after reading, and what the renderer and fitter consume.
//
// Everything is in canvas space: the SVG's intrinsic pixel size (width x height after units and
// the viewBox mapping), with every transform up the tree already applied. Every path is a list
// of subpaths of cubic Bézier segments (lines, quadratics and arcs were converted at read time),
// so the rasteriser and the fitter deal with one primitive. Each path keeps its source element's
// id and a locator plus its full transform to canvas, so results can be written back into the
// user's own document.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "svgmotion/affine.h"

namespace svgm {

// Straight (not premultiplied) sRGB colour, components in [0, 1].
struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

enum class FillRule : uint8_t { NonZero, EvenOdd };
enum class LineJoin : uint8_t { Miter, MiterClip, Round, Bevel };
enum class LineCap : uint8_t { Butt, Round, Square };

// One subpath: points = {p0, c1, c2, p1, c1, c2, p2, ...}, i.e. 1 + 3n points for n cubics.
// A subpath with a single point (a lone "M" or a zero-length "M x y Z") has no segments but
// still matters for round and square caps.
struct Subpath {
  std::vector<Vec2> points;
  bool closed = false;
  size_t segment_count() const { return points.empty() ? 0 : (points.size() - 1) / 3; }
};

struct Stroke {
  Rgba color;              // colour with stroke-opacity folded into a
  double width = 1;        // in canvas units (user width times the transform's mean scale)
  LineJoin join = LineJoin::Miter;
  LineCap cap = LineCap::Butt;
  double miter_limit = 4;  // SVG default
  // Dash and gap lengths (canvas units, even count; empty: solid) and the dash offset. The
  // render draws a dashed stroke solid (with a warning); the Lottie export writes the dashes.
  std::vector<double> dashes;
  double dash_offset = 0;
};

// A gradient paint server, resolved for one element (href chains, units and transforms folded),
// drawn by the forward render (raster/layer_compositor.h) and by the fitter's rasteriser as a
// paint image fixed in canvas space (RasterPlan::paint). The path's flat colour stays the
// gradient's mean stop colour (for the fitter); the Lottie export writes the gradient itself.
enum class Spread : uint8_t { Pad, Reflect, Repeat };

struct GradientStop {
  float offset = 0;  // in [0, 1], non-decreasing along the list
  Rgba color;        // straight colour, stop-opacity folded into a
};

struct Gradient {
  bool radial = false;
  Vec2 p1, p2;               // linear: the gradient vector, in gradient space
  Vec2 center, focal;        // radial: end circle centre and focal point, in gradient space
  double r = 0, fr = 0;      // radial: end and focal radii
  Spread spread = Spread::Pad;
  Affine to_canvas;          // gradient space -> canvas (bounding box units, gradientTransform, CTM)
  std::vector<GradientStop> stops;  // at least one
  float opacity = 1;         // fill-opacity or stroke-opacity of the painted element
  // The element the paint names (its id) and whether its units are the painted element's user
  // space (userSpaceOnUse): the SMIL export moves such a gradient with its path's shape.
  std::string id;
  bool user_space = false;
};

// A compositing layer: an element whose content is drawn offscreen and then composited as one
// (group opacity, clip-path, mask). Only the forward render builds layers; Path::opacity still
// multiplies every ancestor's opacity for the fitter, which composites paths one by one.
struct Layer {
  int parent = -1;   // enclosing layer, -1 for the canvas (or the mask content's own canvas)
  float opacity = 1;
  int clip = -1;     // index into Scene::clips, or -1
  int mask = -1;     // index into Scene::masks, or -1
};

struct Path;

// A clipPath resolved for one element: the union of its shapes' coverage (each under its
// clip-rule, kept in Path::fill_rule), times the coverage of its own clip-path when it has one.
struct ClipPath {
  std::vector<Path> paths;  // canvas space; colours unused
  int clip = -1;            // the clipPath element's own clip-path, index into Scene::clips
};

// A mask resolved for one element: its content drawn like a scene (paths with their paints and
// layers) inside its region, then turned into coverage by luminance (or alpha) times alpha.
struct Mask {
  std::vector<Path> paths;  // canvas space, paint order; their layers end at -1 (the mask's canvas)
  std::vector<Subpath> region;  // the mask's x/y/width/height rectangle in canvas space
  bool luminance = true;        // mask-type: luminance (default) or alpha
  int mask = -1;                // the mask element's own mask, index into Scene::masks
};

struct Path {
  std::string id;          // the element's id, or a generated "path-N" (stable across reads)
  std::string locator;     // where it came from, e.g. "/svg/g[2]/rect[1]" (element index paths)
  std::string tag;         // source element name: path, rect, circle, ...
  std::vector<Subpath> subpaths;  // canvas space
  bool has_fill = true;
  Rgba fill;               // colour with fill-opacity folded into a
  FillRule fill_rule = FillRule::NonZero;
  bool has_stroke = false;
  Stroke stroke;
  float opacity = 1;       // the element's opacity times every ancestor group's opacity
  int group = -1;          // index into Scene::groups, or -1
  Affine to_canvas;        // the element's local user space -> canvas (includes the viewBox map)
  // Forward render only (see Layer and Gradient): the innermost layer holding the path, the
  // part of `opacity` that no layer carries, and gradient paints replacing fill/stroke colours.
  int layer = -1;          // index into Scene::layers, or -1
  float local_opacity = 1;
  int fill_gradient = -1, stroke_gradient = -1;  // indices into Scene::gradients, or -1
};

// A group of paths that move together: today the SVG's top-level <g> elements.
struct Group {
  std::string id;
  std::vector<int> paths;  // indices into Scene::paths, in paint order
  std::string name = {};   // what the part is, when a grouper said so (data-name, grouped_svg.h)
};

// The root attribute that says a document was given room to move (Scene::room).
inline constexpr const char* kRoomAttribute = "data-svgmotion-room";

struct Scene {
  double width = 0, height = 0;  // canvas size in pixels (CSS px)
  // The share of the drawing's own canvas added on each side to give it room to move (the root's
  // data-svgmotion-room, written by pipeline/canvas_room.h): its own canvas is the middle
  // 1 / (1 + 2 room) of this one. 0 when none was given.
  double room = 0;
  std::vector<Path> paths;       // in paint order (first is drawn first, i.e. at the bottom)
  std::vector<Group> groups;
  std::vector<std::string> warnings;  // one line each: element and what was done
  // Forward render only (raster/layer_compositor.h): paint servers, layers, clips and masks.
  std::vector<Gradient> gradients;
  std::vector<Layer> layers;
  std::vector<ClipPath> clips;
  std::vector<Mask> masks;

  // True when drawing the scene needs more than flat colours composited path by path.
  bool needs_layers() const { return !gradients.empty() || !layers.empty(); }

  // Total number of cubic segments over all paths (a size the renderer plans with).
  size_t segment_count() const {
    size_t n = 0;
    for (const auto& p : paths)
      for (const auto& s : p.subpaths) n += s.segment_count();
    return n;
  }
};

}  // namespace svgm
