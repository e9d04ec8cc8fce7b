// Reading <linearGradient> and <radialGradient> into resolved paint servers (svgmotion/scene.h).
//
// A gradient's attributes and stops may come from the gradients its href chain names: each
// attribute is taken from the first element of the chain that sets it (geometry only from
// elements of the same kind; units, transform and spread from either kind), and the stops from
// the first element that has any. The result is resolved for one painted element: bounding box
// units, gradientTransform and the element's transform to canvas are folded into one affine
// map, and the degenerate cases of the spec become what browsers and resvg draw (no stops:
// nothing; one stop, a zero-length vector or a zero radius: the last stop's colour).
#pragma once

#include <pugixml.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "svg/css_sheet.h"
#include "svgmotion/scene.h"

namespace svgm::svg {

// An axis-aligned box in an element's user space (its fill geometry's exact bounds).
struct Box {
  double x = 0, y = 0, w = 0, h = 0;
};

// The exact bounds of cubic subpaths after `m` (extrema of each cubic, not its control points).
// Nothing when there are no points.
std::optional<Box> subpath_bounds(const std::vector<Subpath>& subpaths, const Affine& m = {});

class GradientReader {
 public:
  GradientReader(const std::map<std::string, pugi::xml_node>& ids, const StyleSheet& sheet)
      : ids_(ids), sheet_(sheet) {}

  // The gradient `g` painting an element with fill bounds `bbox` (nothing: empty geometry),
  // whose user space maps to canvas by `ctm`, in a viewport of vp_w x vp_h user units.
  // Nothing when the gradient paints nothing (no stops, bounding box units on an empty box,
  // a singular gradientTransform).
  // At `animation_time` seconds (>= 0), g's own <animateTransform attributeName=
  // "gradientTransform"> children apply.
  std::optional<Gradient> resolve(pugi::xml_node g, const std::optional<Box>& bbox,
                                  const Affine& ctm, double vp_w, double vp_h, double animation_time = -1);

  // The stops of `g` or of the first gradient in its href chain that has any.
  std::vector<GradientStop> stops(pugi::xml_node g);

 private:
  // The chain g, href(g), href(href(g)) ... of gradient elements (cycles cut).
  std::vector<pugi::xml_node> chain(pugi::xml_node g) const;
  GradientStop read_stop(pugi::xml_node stop);

  const std::map<std::string, pugi::xml_node>& ids_;
  const StyleSheet& sheet_;
  std::vector<const CssDeclaration*> matched_;
};

}  // namespace svgm::svg
