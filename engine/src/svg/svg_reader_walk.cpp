// The SVG reader's walk over the elements (svg_reader_internal.h): each element's style,
// transform and compositing layer, then its shape, its <use> target, or its children; top-level
// groups become the scene's groups.
#include <pugixml.hpp>

#include <algorithm>
#include <cmath>

#include "svg/smil_transform.h"
#include "svg/svg_reader_internal.h"
#include "svg/transform_list.h"

namespace svgm::svg {

std::optional<svg::Box> Reader::added_bounds(size_t first, const Affine& ctm) const {
  const std::vector<Path>& paths = sink_ ? *sink_ : scene_.paths;
  const Affine to_user = ctm.inverse();
  std::optional<svg::Box> out;
  for (size_t i = first; i < paths.size(); ++i) {
    const auto b = svg::subpath_bounds(paths[i].subpaths, to_user);
    if (!b) continue;
    if (!out) {
      out = b;
      continue;
    }
    const double x0 = std::min(out->x, b->x), y0 = std::min(out->y, b->y);
    const double x1 = std::max(out->x + out->w, b->x + b->w), y1 = std::max(out->y + out->h, b->y + b->h);
    out = svg::Box{x0, y0, x1 - x0, y1 - y0};
  }
  return out;
}

void Reader::walk_children(pugi::xml_node n, const Style& s, const Affine& ctm, float opacity,
                           const std::string& locator, int group, const std::string& id_prefix,
                           int depth, const Viewport& vp) {
  std::map<std::string, int> seen;
  const bool is_switch = local_name(n.name()) == "switch";
  for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling()) {
    if (c.type() != pugi::node_element) continue;
    const std::string tag(local_name(c.name()));
    const int index = ++seen[tag];  // locators count names without prefix (as smil_writer does)
    if (!in_svg_namespace(c)) continue;  // sodipodi:*, inkscape:*, i:pgf ...
    // Inside a <use> copy (id_prefix set) every shape keeps the use element's locator.
    const std::string loc = !id_prefix.empty() ? locator : locator + "/" + tag + "[" + std::to_string(index) + "]";
    walk(c, s, ctm, opacity, loc, group, id_prefix, depth + 1, vp);
    if (is_switch) break;  // a switch renders its first child (no conditional attributes here)
  }
}

namespace {

// Restores the layer being read when walk leaves an element, by any way out.
struct LayerRestore {
  int& layer;
  int saved;
  ~LayerRestore() { layer = saved; }
};

}  // namespace

// One element: its style and transform, the compositing layer it opens, then its shape, its
// <use> target or its children, and the clip and mask of its layer for the bounds so drawn.
void Reader::walk(pugi::xml_node n, const Style& parent, const Affine& parent_ctm, float opacity,
                  const std::string& locator, int group, const std::string& id_prefix, int depth,
                  const Viewport& vp) {
  count_element(depth);
  const std::string_view tag = local_name(n.name());
  static const std::set<std::string_view> kShapes = {"path", "rect", "circle", "ellipse", "line",
                                                     "polyline", "polygon"};
  const bool shape = kShapes.count(tag) != 0;
  if (!shape && !drawable_container(tag)) return;
  Style s;
  ElementProps props;
  compute_style(n, parent, s, props);
  if (props.display_none) return;
  warn_ignored_effects(n, props);
  Affine ctm;
  if (!element_ctm(n, parent_ctm, ctm)) return;
  const float op = opacity * props.opacity;
  // Every way out of this element (early returns included) leaves the layer it entered in.
  LayerRestore restore{layer_, layer_};
  const ElementLayer layer = open_layer(s, props, shape);
  const size_t first_added = sink_ ? sink_->size() : scene_.paths.size();

  if (shape) {
    std::vector<Subpath> geometry = shape_geometry(n, tag, vp);
    const std::optional<svg::Box> bbox = svg::subpath_bounds(geometry);
    add_shape(n, std::move(geometry), s, ctm, op, locator, group, id_prefix, layer.layered ? 1.0f : props.opacity, vp);
    close_layer(layer, n, props, ctm, bbox, vp, depth);
    return;
  }
  if (clip_content_ && tag != "use") return;  // a clipPath holds shapes and uses of shapes
  if (tag == "use") {
    if (walk_use(n, s, ctm, op, locator, group, id_prefix, depth, vp))
      close_layer(layer, n, props, ctm, added_bounds(first_added, ctm), vp, depth);
    return;
  }
  Viewport inner = vp;
  if (tag == "svg" && depth > 0 && !enter_nested_svg(n, vp, ctm, inner)) return;
  bool new_group = false;
  const int g = tag == "g" && depth == 1 ? open_top_level_group(n, group, new_group) : group;
  walk_children(n, s, ctm, op, locator, g, id_prefix, depth, inner);
  close_layer(layer, n, props, ctm, added_bounds(first_added, ctm), vp, depth);
  if (new_group) close_top_level_group(g);
}

// The reader's bounds on nesting and on the elements one document may ask it to draw.
void Reader::count_element(int depth) {
  if (depth > limits_.max_depth) fail("nesting deeper than " + std::to_string(limits_.max_depth) + " elements");
  if (++visited_ > kMaxVisited)
    fail("more than " + std::to_string(kMaxVisited) + " elements to draw (nested <use> copies)");
}

// Whether an element that is not a shape is drawn (a container, a use, a nested svg); content
// we cannot draw is counted for its warning.
bool Reader::drawable_container(std::string_view tag) {
  static const std::set<std::string_view> kContainers = {"g", "a", "switch"};
  if (kContainers.count(tag) || tag == "use" || tag == "svg") return true;
  if (tag == "text") warn_skipped(tag, "skipped (text is not supported)");
  else if (tag == "image") warn_skipped(tag, "skipped (images are not supported)");
  else if (tag == "foreignObject") warn_skipped(tag, "skipped (foreignObject is not supported)");
  else if (tag == "video" || tag == "audio" || tag == "canvas" || tag == "iframe")
    warn_skipped(tag, "skipped (not supported)");
  return false;  // defs, symbol (only through use), title, metadata, editor elements ...
}

// Effects the element asks for that are drawn without: one warning per kind.
void Reader::warn_ignored_effects(pugi::xml_node n, const ElementProps& props) {
  if (clip_content_ && (props.has_clip || props.has_mask))
    warn(n, "clip-path or mask inside a clipPath ignored");
  if (!clip_content_ && props.has_clip && props.clip_url.empty())
    warn(n, "clip-path ignored (only url(#id) references are supported)");
  if (!clip_content_ && props.has_mask && props.mask_url.empty())
    warn(n, "mask ignored (only url(#id) references are supported)");
  if (props.has_filter) warn(n, "filter ignored (filters are not supported)");
  if (props.has_marker) warn(n, "markers ignored (markers are not supported)");
}

// The element's transform to canvas space (its own transform, animated at the reader's time,
// after its parent's); false when it is singular and the element draws nothing.
bool Reader::element_ctm(pugi::xml_node n, const Affine& parent_ctm, Affine& ctm) {
  Affine own;
  if (const char* t = n.attribute("transform").value(); *t) {
    bool bad = false;
    const auto m = svg::parse_transform(t, &bad);
    if (bad) fail(describe(n) + " transform: number out of range");
    if (m) own = *m;
    else warn(n, "invalid transform ignored");  // as resvg and browsers do
  }
  if (limits_.animation_time >= 0) own = svg::animated_transform(n, limits_.animation_time, own);
  ctm = parent_ctm * own;
  // A singular transform (e.g. scale(0)) draws nothing, and has no inverse for exporters. One
  // whose determinant overflows (scale(1e200)) puts everything beyond max_coordinate: refused
  // like the coordinates it makes, not silently dropped.
  if (const double det = ctm.det(); !std::isfinite(det))
    fail(describe(n) + ": scale to canvas space too large (its transforms and the viewBox overflow)");
  else if (!(std::fabs(det) > 0))
    return false;
  return true;
}

// A compositing layer (scene.h) for group opacity, clip-path and mask. A shape's opacity is
// folded into its paint when it has a fill or a stroke but not both (one draw, one blend).
Reader::ElementLayer Reader::open_layer(const Style& s, const ElementProps& props, bool shape) {
  ElementLayer l;
  const bool both_paints = s.fill.kind != PaintKind::None && s.stroke.kind != PaintKind::None && s.stroke_width > 0;
  l.clipped = !clip_content_ && !props.clip_url.empty();
  l.masked = !clip_content_ && !props.mask_url.empty();
  l.layered = !clip_content_ && (l.clipped || l.masked || (props.opacity < 1 && (!shape || both_paints)));
  l.saved = layer_;
  if (l.layered) {
    l.own = static_cast<int>(scene_.layers.size());
    scene_.layers.push_back({layer_, props.opacity, -1, -1});
    layer_ = l.own;
  }
  return l;
}

// Clip and mask are resolved once the content is read, for its bounding box.
void Reader::close_layer(const ElementLayer& l, pugi::xml_node n, const ElementProps& props,
                         const Affine& ctm, const std::optional<svg::Box>& bbox, const Viewport& vp,
                         int depth) {
  layer_ = l.saved;
  if (l.own < 0) return;
  if (l.clipped) {
    const int c = resolve_clip(props.clip_url, n, ctm, bbox, vp, depth);
    scene_.layers[l.own].clip = c;
  }
  if (l.masked) {
    const int m = resolve_mask(props.mask_url, n, ctm, bbox, vp, depth);
    scene_.layers[l.own].mask = m;
  }
}

// A <use>: its target drawn in place, moved by x and y (`ctm` becomes the target's transform).
// False when nothing is referenced (an external or missing target: a warning).
bool Reader::walk_use(pugi::xml_node n, const Style& s, Affine& ctm, float op,
                      const std::string& locator, int group, const std::string& id_prefix, int depth,
                      const Viewport& vp) {
  const char* href = n.attribute("xlink:href").value();
  if (!*href) href = n.attribute("href").value();
  if (*href != '#') {
    if (*href) warn(n, "external references are not supported (skipped)");
    return false;
  }
  const auto it = ids_.find(href + 1);
  if (it == ids_.end()) {
    warn(n, "reference to a missing element skipped");
    return false;
  }
  const pugi::xml_node target = it->second;
  if (use_stack_.count(target.internal_object()) || use_stack_.count(n.internal_object()))
    fail(describe(n) + " references itself (use cycle)");
  for (pugi::xml_node up = n.parent(); up; up = up.parent())
    if (up == target) fail(describe(n) + " references itself (use cycle)");
  use_stack_.insert(n.internal_object());
  use_stack_.insert(target.internal_object());
  ctm = ctm * Affine::translate(length(n, "x", 0, vp.w), length(n, "y", 0, vp.h));
  // Ids of shapes drawn through a use: "<use id>/<shape id>", nested uses chained; a use
  // without an id is "use-N" (N counts such uses in drawing order).
  const char* uid = n.attribute("id").value();
  const std::string own = *uid ? std::string(uid) : "use-" + std::to_string(++anonymous_uses_);
  const std::string prefix = id_prefix.empty() ? own : id_prefix + "/" + own;
  const int g = group < 0 && depth == 1 ? -2 : group;  // top-level use: one group of its own
  int use_group = g;
  if (g == -2) {
    use_group = static_cast<int>(scene_.groups.size());
    scene_.groups.push_back({prefix, {}});
  }
  if (local_name(target.name()) == "symbol") {
    walk_symbol(n, target, s, ctm, op, locator, use_group, prefix, depth, vp);
  } else {
    walk(target, s, ctm, op, locator, use_group, prefix, depth + 1, vp);
  }
  if (g == -2 && scene_.groups[use_group].paths.empty()) scene_.groups.pop_back();
  use_stack_.erase(n.internal_object());
  use_stack_.erase(target.internal_object());
  return true;
}

// A <symbol> drawn through a <use>: its viewBox fitted to the use's width and height, its own
// style and opacity (a layer of its own when not opaque).
void Reader::walk_symbol(pugi::xml_node n, pugi::xml_node target, const Style& s, const Affine& ctm,
                         float op, const std::string& locator, int use_group,
                         const std::string& prefix, int depth, const Viewport& vp) {
  Viewport inner;
  const double w = length(n, "width", vp.w, vp.w), h = length(n, "height", vp.h, vp.h);
  const Affine vb = viewbox_transform(target, w, h, &inner);
  Style ts;
  ElementProps tp;
  compute_style(target, s, ts, tp);
  if (!tp.display_none && w > 0 && h > 0) {
    const int outer = layer_;
    if (tp.opacity < 1 && !clip_content_) {
      scene_.layers.push_back({layer_, tp.opacity, -1, -1});
      layer_ = static_cast<int>(scene_.layers.size()) - 1;
    }
    walk_children(target, ts, ctm * vb, op * tp.opacity, locator, use_group, prefix, depth + 1, inner);
    layer_ = outer;
  }
}

// A nested <svg>: its viewport placed and its viewBox fitted into it (`ctm` and `inner` become
// its content's); false when it has no area.
bool Reader::enter_nested_svg(pugi::xml_node n, const Viewport& vp, Affine& ctm, Viewport& inner) {
  const double w = length(n, "width", vp.w, vp.w), h = length(n, "height", vp.h, vp.h);
  if (!(w > 0) || !(h > 0)) return false;
  ctm = ctm * Affine::translate(length(n, "x", 0, vp.w), length(n, "y", 0, vp.h)) *
        viewbox_transform(n, w, h, &inner);
  warn(n, "nested <svg> drawn without clipping to its viewport");
  return true;
}

// A top-level group is a part that moves together: the scene group its paths go to, a new one
// (`new_group`) unless a run of the same part came before.
int Reader::open_top_level_group(pugi::xml_node n, int group, bool& new_group) {
  int g = group;
  // Runs of one part split by paint order (grouped_svg.h) share a data-group: join them.
  const char* part = n.attribute("data-group").value();
  const auto joined = *part ? data_groups_.find(part) : data_groups_.end();
  if (joined != data_groups_.end()) {
    g = joined->second;
  } else {
    g = static_cast<int>(scene_.groups.size());
    const char* id = n.attribute("id").value();
    scene_.groups.push_back({*part ? part : *id ? id : "group-" + std::to_string(g + 1), {}, n.attribute("data-name").value()});
    if (*part) data_groups_[part] = g;
    new_group = true;
  }
  return g;
}

// A new top-level group that drew nothing is dropped, and its data-group forgotten.
void Reader::close_top_level_group(int g) {
  if (scene_.groups[g].paths.empty()) {
    scene_.groups.pop_back();
    for (auto it = data_groups_.begin(); it != data_groups_.end();)
      it = it->second == g ? data_groups_.erase(it) : std::next(it);
  }
}

}  // namespace svgm::svg
