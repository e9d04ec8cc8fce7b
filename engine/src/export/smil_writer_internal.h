// What the SMIL writer's files share (smil_writer.cpp: the pass, path data and these helpers;
// smil_full_writer.cpp: the full export; smil_compact_writer.cpp: the compact export;
// smil_gradient_motion.cpp: user-space gradients carried with their shapes). Not part of the
// engine's interface: include it only from those files.
#pragma once

#include <pugixml.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "export/smil_writer.h"

namespace svgm::smil_internal {

void append_number(std::string& s, double v, int decimals);

std::string_view local_name(const char* name);

// The output file: the user's own bytes before and after the root element (declaration,
// comments, doctype and the whitespace between them, which pugixml does not keep at the
// document level) around the root element as changed. `root_begin` is where the root's '<'
// stands in `original`.
std::string with_original_prolog(const std::string& original, size_t root_begin, pugi::xml_node root);

inline constexpr const char* kShapeGeometry[] = {"x", "y", "width", "height", "rx", "ry", "cx",
                                          "cy", "r", "x1", "y1", "x2", "y2", "points"};

// Decimal places of written angles (degrees) and scale factors: finer than the coordinates'
// so that a rotation or scale about a far origin still lands within a coordinate's rounding
// (1e-4 degrees moves a point 1000 units away by 0.002; 1e-6 of scale, by 0.001).
inline constexpr int kAngleDecimals = 4, kScaleDecimals = 6;

double rounded(double v, int decimals);

// The document's gradient elements by id, and how many times each id is named as a paint or
// link target (url(#id) in any attribute or <style> text, href="#id" with or without xlink:),
// read in one walk. A gradient named once paints one shape and no other gradient inherits it.
struct GradientIndex {
  std::map<std::string, pugi::xml_node, std::less<>> gradients;
  std::map<std::string, int, std::less<>> references;
};

// The user-space gradients a writer moves with their shapes, each element once: a gradient
// this shape alone paints with (named once, not inheriting through its href without a
// transform of its own), with its own gradientTransform. Shared ones are counted for the
// writer's one warning (moving them for this shape would move them wrongly elsewhere).
struct UserGradients {
  const pugi::xml_document& doc;
  std::optional<GradientIndex> index;  // read on the first user-space gradient
  std::set<std::string> seen;
  int shared = 0;
  struct Own {
    pugi::xml_node node;
    Affine transform;  // its gradientTransform (identity when none)
  };
  std::optional<Own> claim(const Gradient& g);
};

// The gradient transform that carries a user-space gradient `g` along with its path's shape,
// per written value: the similarity from the path's points at rest to its points in that value
// that keeps their colours (fit_colour_similarity), in the path's own coordinates, before the
// gradient's own transform `own`. Nothing when the shape only ever moves by less than the
// written precision, or when its outline does not show its motion along the ramp
// (colour_visibility): the gradient then stays where the document and the fit put it.
std::optional<std::vector<TransformParts>> gradient_motion(const Path& path, const Gradient& g, Vec2 canvas,
                                                           const RasterPlan& plan, int f, const std::vector<double>& points, int keyframes,
                                                           const Affine& own, int decimals);

// The user's document again, as the writers add to it: its text (kept for what precedes the
// root element) and the parsed tree; returns the root element's name offset in the text.
ptrdiff_t reread_source(const std::filesystem::path& source, std::string& original, pugi::xml_document& doc);

// Every path's element in the re-read document (by its locator); throws when one is missing.
std::vector<pugi::xml_node> find_elements(pugi::xml_document& doc, const Scene& scene,
                                          const std::filesystem::path& source);

// Removes an earlier fit's gradientTransform animation from gradient element `gn`.
void remove_gradient_animations(pugi::xml_node gn);

// An animation's clock: its duration `dur` ("2s"), then played once and held (fill freeze) or
// repeated forever, as `loop` says (a mirrored loop's values already go there and back).
void append_repeat(pugi::xml_node anim, const char* dur, LoopMode loop);

}  // namespace svgm::smil_internal
