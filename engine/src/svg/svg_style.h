// Computed style of an SVG element: presentation attributes and the `style` attribute over
// the inherited values, as the reader walks the tree.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "svgmotion/scene.h"

namespace svgm::svg {

enum class PaintKind { None, Color, CurrentColor, Url };

struct Paint {
  PaintKind kind = PaintKind::None;
  Rgba color;             // for Color (and the fallback of Url)
  std::string url;        // element id for Url
  bool has_fallback = false;
  PaintKind fallback = PaintKind::None;
};

// Inherited properties (CSS inheritance); opacity and display are per element.
struct Style {
  Paint fill{PaintKind::Color, {0, 0, 0, 1}, {}, false, PaintKind::None};
  Paint stroke;
  float fill_opacity = 1, stroke_opacity = 1;
  FillRule fill_rule = FillRule::NonZero;
  double stroke_width = 1;  // user units
  LineJoin join = LineJoin::Miter;
  LineCap cap = LineCap::Butt;
  double miter_limit = 4;
  Rgba color{0, 0, 0, 1};   // `color`, for currentColor
  bool visible = true;
  bool dashed = false;      // stroke-dasharray given (drawn solid, with a warning)
  // The dash pattern (user units; even length, empty when solid or unreadable) and its offset:
  // the render draws dashed strokes solid, the Lottie export writes them.
  std::vector<double> dash_array;
  double dash_offset = 0;
  FillRule clip_rule = FillRule::NonZero;  // for shapes inside a clipPath
};

// Per-element, non-inherited values found while applying a declaration.
struct ElementProps {
  float opacity = 1;
  bool display_none = false;
  bool has_clip = false, has_mask = false, has_filter = false, has_marker = false;
  std::string clip_url, mask_url;  // the element id of clip-path / mask url(#id), when given so
  std::string mask_type;           // mask-type (on a <mask>): luminance or alpha
};

// Applies one declaration `name: value` (a presentation attribute or a `style` entry).
// Returns false for a number that is nan/inf/overflowing (the document is malformed).
bool apply_declaration(std::string_view name, std::string_view value, const Style& parent,
                       Style& style, ElementProps& props);

// Parses an opacity-like value: number or percentage, clamped to [0, 1].
bool parse_unit_interval(std::string_view v, float* out);

}  // namespace svgm::svg
