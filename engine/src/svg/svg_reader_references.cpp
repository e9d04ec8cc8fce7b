// The SVG reader's clip paths and masks (svg_reader_internal.h): a clip-path or mask
// reference resolved, with cycle detection, into the scene's clips and masks, their content
// walked into its own list of paths rather than the scene's.
#include <pugixml.hpp>

#include <cmath>

#include "svg/svg_reader_internal.h"
#include "svg/transform_list.h"

namespace svgm::svg {

void Reader::walk_content(pugi::xml_node n, const Style& s, const Affine& ctm, bool clip,
                          std::vector<Path>* sink, int depth, const Viewport& vp) {
  // Content paths get no ids of their own: the generated ids of the scene's paths stay what
  // they were without it.
  const int generated = generated_, uses = anonymous_uses_;
  std::vector<Path>* outer_sink = sink_;
  const bool outer_clip = clip_content_;
  const int outer_layer = layer_;
  sink_ = sink;
  clip_content_ = clip;
  layer_ = -1;
  walk_children(n, s, ctm, 1.0f, "", -1, "content", depth + 1, vp);
  sink_ = outer_sink;
  clip_content_ = outer_clip;
  layer_ = outer_layer;
  generated_ = generated;
  anonymous_uses_ = uses;
}

// The `kind` element that `url` names, now on the reference stack (the caller erases it), or a
// null node after one warning when there is none or it is already being resolved (a cycle).
pugi::xml_node Reader::enter_reference(const std::string& url, pugi::xml_node el, const char* kind,
                                       const char* property, const char* fallback) {
  const auto it = ids_.find(url);
  const std::string what = std::string(property) + " url(#" + url + ")";
  if (it == ids_.end() || local_name(it->second.name()) != kind) {
    warn(el, what + " is not a " + kind + " (" + fallback + ")");
    return {};
  }
  if (!reference_stack_.insert(it->second.internal_object()).second) {
    warn(el, what + " refers to itself (" + fallback + ")");
    return {};
  }
  return it->second;
}

int Reader::resolve_clip(const std::string& url, pugi::xml_node el, const Affine& ctm,
                         const std::optional<svg::Box>& bbox, const Viewport& vp, int depth) {
  const pugi::xml_node node = enter_reference(url, el, "clipPath", "clip-path", "drawn unclipped");
  if (!node) return -1;
  Style cs;
  ElementProps cp;
  compute_style(node, Style{}, cs, cp);
  Affine m = ctm;
  if (const char* t = node.attribute("transform").value(); *t)
    if (const auto tm = svg::parse_transform(t)) m = m * *tm;
  const int index = static_cast<int>(scene_.clips.size());
  scene_.clips.emplace_back();
  const bool bbox_units = std::string_view(node.attribute("clipPathUnits").value()) == "objectBoundingBox";
  // Bounding box units on an empty box clip everything away (the element is not drawn).
  if (!bbox_units || (bbox && bbox->w > 0 && bbox->h > 0)) {
    if (bbox_units) m = m * Affine{bbox->w, 0, 0, bbox->h, bbox->x, bbox->y};
    std::vector<Path> paths;
    if (std::fabs(m.det()) > 0 && std::isfinite(m.det())) walk_content(node, cs, m, true, &paths, depth, vp);
    scene_.clips[index].paths = std::move(paths);
  }
  if (cp.has_clip && !cp.clip_url.empty()) {
    const int nested = resolve_clip(cp.clip_url, node, ctm, bbox, vp, depth);
    scene_.clips[index].clip = nested;
  }
  reference_stack_.erase(node.internal_object());
  return index;
}

int Reader::resolve_mask(const std::string& url, pugi::xml_node el, const Affine& ctm,
                         const std::optional<svg::Box>& bbox, const Viewport& vp, int depth) {
  const pugi::xml_node node = enter_reference(url, el, "mask", "mask", "drawn unmasked");
  if (!node) return -1;
  Style ms;
  ElementProps mp;
  compute_style(node, Style{}, ms, mp);
  const int index = static_cast<int>(scene_.masks.size());
  scene_.masks.emplace_back();
  scene_.masks[index].luminance = mp.mask_type != "alpha";
  const bool box_ok = bbox && bbox->w > 0 && bbox->h > 0;
  const bool region_bbox = std::string_view(node.attribute("maskUnits").value()) != "userSpaceOnUse";
  const bool content_bbox = std::string_view(node.attribute("maskContentUnits").value()) == "objectBoundingBox";
  // The region: x, y, width, height (default -10%, -10%, 120%, 120%) in bounding box fractions
  // or user units; with bounding box units on an empty box the region is empty (nothing drawn).
  if (!region_bbox || box_ok) {
    double x, y, w, h;
    Affine to_user;
    if (region_bbox) {
      x = length(node, "x", -0.1, 1), y = length(node, "y", -0.1, 1);
      w = length(node, "width", 1.2, 1), h = length(node, "height", 1.2, 1);
      to_user = Affine{bbox->w, 0, 0, bbox->h, bbox->x, bbox->y};
    } else {
      x = length(node, "x", -0.1 * vp.w, vp.w), y = length(node, "y", -0.1 * vp.h, vp.h);
      w = length(node, "width", 1.2 * vp.w, vp.w), h = length(node, "height", 1.2 * vp.h, vp.h);
    }
    if (w > 0 && h > 0) {
      const Affine m = ctm * to_user;
      Subpath r;
      r.closed = true;
      const Vec2 corners[] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}, {x, y}};
      r.points.push_back(m.apply(corners[0]));
      for (int i = 1; i < 5; ++i) {
        const Vec2 a = m.apply(corners[i - 1]), b = m.apply(corners[i]);
        r.points.insert(r.points.end(), {a + (1.0 / 3.0) * (b - a), a + (2.0 / 3.0) * (b - a), b});
      }
      scene_.masks[index].region.push_back(std::move(r));
    }
  }
  if (!content_bbox || box_ok) {
    Affine m = ctm;
    if (content_bbox) m = m * Affine{bbox->w, 0, 0, bbox->h, bbox->x, bbox->y};
    std::vector<Path> paths;
    walk_content(node, ms, m, false, &paths, depth, vp);
    scene_.masks[index].paths = std::move(paths);
  }
  if (mp.has_mask && !mp.mask_url.empty()) {
    const int nested = resolve_mask(mp.mask_url, node, ctm, bbox, vp, depth);
    scene_.masks[index].mask = nested;
  }
  reference_stack_.erase(node.internal_object());
  return index;
}

}  // namespace svgm::svg
