// The SVG reader's state and steps, shared by the files that implement it (svg_reader.cpp:
// the document, cascade and warnings; svg_reader_walk.cpp: the element walk; svg_reader_shapes.cpp:
// geometry and paths; svg_reader_paint.cpp: paints; svg_reader_references.cpp: clip paths and
// masks). Internal to the svg folder: the public entry points are in svgmotion/svg_reader.h.
#pragma once

#include <pugixml.hpp>

#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "svg/css_sheet.h"
#include "svg/gradient_reader.h"
#include "svg/svg_style.h"
#include "svgmotion/error.h"
#include "svgmotion/scene.h"
#include "svgmotion/svg_reader.h"

namespace svgm::svg {

// An element's name without its namespace prefix.
std::string_view local_name(const char* name);

// "<tag id=x>", for messages.
std::string describe(pugi::xml_node n);

// A size or coordinate for a message: whole pixels, or %g beyond 15 digits. Never a cast to an
// integer type, which is undefined behaviour for 1e308.
std::string px_text(double v);

struct Viewport {
  double w = 100, h = 100;
};

// Elements walked in one document, copies through <use> included: bounds the work a small
// file of nested uses (each instantiating the previous one twice) can ask for.
constexpr size_t kMaxVisited = 1u << 20;

class Reader {
 public:
  Reader(std::string name, const SvgReadLimits& limits) : name_(std::move(name)), limits_(limits) {}

  Scene read(std::string_view text);

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw Error(name_ + ": " + problem); }

  // Numeric attribute as a length in user units; `fallback` when absent or invalid. Throws on
  // nan/inf/overflow.
  double length(pugi::xml_node n, const char* attr, double fallback, double percent_of) const;
  bool has(pugi::xml_node n, const char* attr) const { return !n.attribute(attr).empty(); }

  void compute_style(pugi::xml_node n, const Style& parent, Style& s, ElementProps& props);
  void walk(pugi::xml_node n, const Style& parent, const Affine& ctm, float opacity,
            const std::string& locator, int group, const std::string& id_prefix, int depth,
            const Viewport& vp);
  void walk_children(pugi::xml_node n, const Style& s, const Affine& ctm, float opacity,
                     const std::string& locator, int group, const std::string& id_prefix,
                     int depth, const Viewport& vp);
  // The steps of walk (svg_reader_walk.cpp), in the order it takes them.
  void count_element(int depth);
  bool drawable_container(std::string_view tag);
  void warn_ignored_effects(pugi::xml_node n, const ElementProps& props);
  bool element_ctm(pugi::xml_node n, const Affine& parent_ctm, Affine& ctm);
  // The compositing layer an element opened (none: own < 0), and the one to return to.
  struct ElementLayer {
    bool layered = false, clipped = false, masked = false;
    int own = -1, saved = -1;
  };
  ElementLayer open_layer(const Style& s, const ElementProps& props, bool shape);
  void close_layer(const ElementLayer& layer, pugi::xml_node n, const ElementProps& props,
                   const Affine& ctm, const std::optional<svg::Box>& bbox, const Viewport& vp,
                   int depth);
  bool walk_use(pugi::xml_node n, const Style& s, Affine& ctm, float opacity,
                const std::string& locator, int group, const std::string& id_prefix, int depth,
                const Viewport& vp);
  void walk_symbol(pugi::xml_node n, pugi::xml_node target, const Style& s, const Affine& ctm,
                   float opacity, const std::string& locator, int use_group,
                   const std::string& prefix, int depth, const Viewport& vp);
  bool enter_nested_svg(pugi::xml_node n, const Viewport& vp, Affine& ctm, Viewport& inner);
  int open_top_level_group(pugi::xml_node n, int group, bool& new_group);
  void close_top_level_group(int g);
  void add_shape(pugi::xml_node n, std::vector<Subpath> subpaths, const Style& s,
                 const Affine& ctm, float opacity, const std::string& locator, int group,
                 const std::string& id_prefix, float local_opacity, const Viewport& vp);
  // Clip paths and masks of an element (scene.h's ClipPath and Mask), for an element whose user
  // space maps to canvas by `ctm` and whose fill bounds there are `bbox`. -1 when the reference
  // is missing or recursive (drawn unclipped or unmasked, with a warning).
  pugi::xml_node enter_reference(const std::string& url, pugi::xml_node el, const char* kind,
                                 const char* property, const char* fallback);
  int resolve_clip(const std::string& url, pugi::xml_node el, const Affine& ctm,
                   const std::optional<svg::Box>& bbox, const Viewport& vp, int depth);
  int resolve_mask(const std::string& url, pugi::xml_node el, const Affine& ctm,
                   const std::optional<svg::Box>& bbox, const Viewport& vp, int depth);
  // Walks the children of a <clipPath> or <mask> into `sink` instead of the scene's paths.
  void walk_content(pugi::xml_node n, const Style& s, const Affine& ctm, bool clip,
                    std::vector<Path>* sink, int depth, const Viewport& vp);
  // The bounds, in the user space of `ctm`, of the paths added to the current output from index
  // `first` on (a container's bounding box).
  std::optional<svg::Box> added_bounds(size_t first, const Affine& ctm) const;
  std::vector<Subpath> shape_geometry(pugi::xml_node n, std::string_view tag, const Viewport& vp);
  bool animated_path(pugi::xml_node n, double time, std::vector<Subpath>& out);
  // A paint's flat colour; `gradient` is set to the gradient element of a gradient paint.
  bool resolve_paint(const Paint& p, const Style& s, pugi::xml_node el, Rgba* out,
                     pugi::xml_node* gradient);
  std::optional<Rgba> gradient_mean(pugi::xml_node g, int depth);
  Affine viewbox_transform(pugi::xml_node n, double w, double h, Viewport* inner);
  // Unsupported features: one warning line per kind, naming the first element and counting
  // the others, in order of first occurrence.
  void warn(pugi::xml_node n, const std::string& what) { note(what, describe(n), false); }
  void warn_skipped(std::string_view tag, const char* reason) {
    note("<" + std::string(tag) + "> " + reason, {}, true);
  }
  void note(const std::string& key, std::string first, bool skipped);
  std::vector<std::string> warning_lines() const;
  void collect_styles(pugi::xml_node root);
  // False for elements with a namespace prefix other than the root's (editor extensions).
  bool in_svg_namespace(pugi::xml_node n) const {
    const char* colon = std::strchr(n.name(), ':');
    if (!colon) return true;
    const std::string_view prefix(n.name(), static_cast<size_t>(colon - n.name()));
    return prefix == root_prefix_ || prefix == "svg";
  }

  std::string name_;
  SvgReadLimits limits_;
  Scene scene_;
  std::map<std::string, pugi::xml_node> ids_;
  std::map<std::string, int> data_groups_;  // data-group of top-level <g> runs -> group
  std::set<const void*> use_stack_;
  struct WarningKind {
    std::string key, first;
    int count = 0;
    bool skipped = false;
  };
  std::vector<WarningKind> warnings_;
  svg::StyleSheet sheet_;
  svg::GradientReader gradient_reader_{ids_, sheet_};
  // Where shapes go: the scene's paths, or a clip path's or mask's content while one is read.
  std::vector<Path>* sink_ = nullptr;
  bool clip_content_ = false;  // inside a <clipPath>: geometry only, clip-rule for fill-rule
  int layer_ = -1;             // the innermost compositing layer being read (Scene::layers)
  std::set<const void*> reference_stack_;  // clipPath and mask elements being resolved
  std::string root_prefix_;
  std::vector<const svg::CssDeclaration*> matched_;
  int generated_ = 0;
  int anonymous_uses_ = 0;
  size_t segments_ = 0;
  size_t visited_ = 0;  // elements walked, <use> instances included (bounds "use bombs")
};

}  // namespace svgm::svg
