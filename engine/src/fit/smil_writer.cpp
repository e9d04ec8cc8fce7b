// The SMIL animation writer (see smil_writer.h).
#include "fit/smil_writer.h"
#include "svgmotion/atomic_file.h"

#include <pugixml.hpp>

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>


#include "fit/document_order.h"
#include "svg/svg_number.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

void append_number(std::string& s, double v, int decimals) {
  svg::append_rounded(s, v, std::pow(10.0, decimals));
}

std::string_view local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

// The output file: the user's own bytes before and after the root element (declaration,
// comments, doctype and the whitespace between them, which pugixml does not keep at the
// document level) around the root element as changed. `root_begin` is where the root's '<'
// stands in `original`.
std::string with_original_prolog(const std::string& original, size_t root_begin, pugi::xml_node root) {
  const std::string close = std::string("</") + root.name();
  size_t root_end = original.rfind(close);
  if (root_end != std::string::npos) root_end = original.find('>', root_end);
  std::ostringstream body;
  root.print(body, "", pugi::format_raw, pugi::encoding_utf8);
  if (root_end == std::string::npos || root_end < root_begin) return body.str();
  return original.substr(0, root_begin) + body.str() + original.substr(root_end + 1);
}

constexpr const char* kShapeGeometry[] = {"x", "y", "width", "height", "rx", "ry", "cx",
                                          "cy", "r", "x1", "y1", "x2", "y2", "points"};

}  // namespace

LoopMode parse_loop_mode(const std::string& text, const std::string& what) {
  if (text == "loop") return LoopMode::Loop;
  if (text == "once") return LoopMode::Once;
  if (text == "mirror") return LoopMode::Mirror;
  throw Error(what + " must be loop, once or mirror, not '" + text + "'");
}

const char* loop_mode_name(LoopMode m) {
  switch (m) {
    case LoopMode::Loop: return "loop";
    case LoopMode::Once: return "once";
    case LoopMode::Mirror: return "mirror";
  }
  return "loop";
}

AnimationPass animation_pass(const AnimationTiming& timing) {
  const int K = timing.keyframes;
  AnimationPass pass;
  for (int k = 0; k < K; ++k) {
    pass.seq.push_back(timing.close_loop && K > 1 && k == K - 1 ? 0 : k);
    pass.times.push_back(!timing.key_times.empty() ? timing.key_times[static_cast<size_t>(k)]
                         : K > 1 ? static_cast<double>(k) / (K - 1) : 0.0);
  }
  pass.duration_s = timing.duration_s;
  if (timing.loop == LoopMode::Mirror && K > 1) {
    for (int k = K - 2; k >= 0; --k) {
      pass.seq.push_back(pass.seq[static_cast<size_t>(k)]);
      pass.times.push_back(2.0 - pass.times[static_cast<size_t>(k)]);
    }
    for (double& t : pass.times) t /= 2;
    pass.duration_s *= 2;
  }
  return pass;
}

std::string path_data(const Path& path, const double* cp, const Affine& to_local, int decimals) {
  std::string d;
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    for (size_t i = 0; i < sp.points.size(); ++i) {
      const Vec2 q = to_local.apply({cp[2 * i], cp[2 * i + 1]});
      if (i == 0) d += d.empty() ? "M" : " M";
      else if (i % 3 == 1) d += " C";
      d += ' ';
      append_number(d, q.x, decimals);
      d += ' ';
      append_number(d, q.y, decimals);
    }
    if (sp.closed) d += " Z";
    cp += 2 * sp.points.size();
  }
  return d;
}

void check_animation_inputs(const Scene& scene, const RasterPlan& plan, const std::vector<double>& points,
                            const AnimationTiming& timing, const ExportMap* map, int decimals) {
  const int K = timing.keyframes;
  if (decimals < 0 || decimals > kMaxDecimals) throw Error("internal: export precision out of range");
  if (K < 1 || points.size() != static_cast<size_t>(K) * plan.n_cp * 2)
    throw Error("internal: animation points do not match the plan");
  if (!timing.key_times.empty() && timing.key_times.size() != static_cast<size_t>(K))
    throw Error("internal: key times do not match the keyframes");
  if (map && map->fitted_of.size() != scene.paths.size())
    throw Error("internal: export map does not match the document");
}

std::vector<std::string> write_animation_svg(const fs::path& source, const Scene& scene,
                                             const RasterPlan& plan,
                                             const std::vector<double>& points,
                                             const AnimationTiming& timing, const fs::path& out,
                                             const ExportMap* map, int decimals) {
  check_animation_inputs(scene, plan, points, timing, map, decimals);
  std::ifstream in(source, std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw Error(source.string() + ": cannot re-read for export");
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(original.data(), original.size(), kKeepDocumentParse);
  if (!parsed) throw Error(source.string() + ": cannot re-read for export: " + parsed.description());
  const ptrdiff_t root_name_at = doc.document_element().offset_debug();

  const AnimationPass pass = animation_pass(timing);
  const std::vector<int>& seq = pass.seq;
  const std::vector<double>& times = pass.times;
  const double duration = pass.duration_s;
  std::string key_times;
  for (size_t i = 0; i < times.size(); ++i) {
    if (i) key_times += ';';
    // 1/10000 of a pass: finer than any frame, and the last is exactly 1 as SMIL requires.
    const double t = i + 1 == times.size() ? 1.0 : std::round(times[i] * 1e4) / 1e4;
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, t);
    key_times.append(buf, ec == std::errc() ? p : buf);
  }
  char dur[32];
  std::snprintf(dur, sizeof dur, "%.4gs", duration);

  std::vector<std::string> warnings;
  int skipped_use = 0;
  // Find every element before changing any: turning a <rect> into a <path> renumbers the
  // locators of the paths after it.
  std::vector<pugi::xml_node> elements;
  for (const Path& path : scene.paths) {
    elements.push_back(find_locator(doc, path.locator));
    if (!elements.back()) throw Error("internal: " + path.locator + " not found in " + source.string());
  }
  for (size_t p = 0; p < scene.paths.size(); ++p) {
    const Path& path = scene.paths[p];
    const int f = map ? map->fitted_of[p] : static_cast<int>(p);
    if (f < 0 || plan.path_cp_count[static_cast<size_t>(f)] == 0) continue;
    const size_t first = plan.path_cp_first[static_cast<size_t>(f)];
    pugi::xml_node el = elements[p];
    const std::string_view tag = local_name(el.name());
    if (tag == "use") {
      ++skipped_use;
      continue;
    }
    const Affine to_local = path.to_canvas.inverse();
    std::string values;
    for (size_t i = 0; i < seq.size(); ++i) {
      if (i) values += ';';
      values += path_data(path, &points[(static_cast<size_t>(seq[i]) * plan.n_cp + first) * 2], to_local, decimals);
    }
    if (tag != "path") {
      // Only <path> has a `d`: turn the shape into one, keeping id, paint and transform.
      for (const char* a : kShapeGeometry) el.remove_attribute(a);
      const std::string prefix(el.name(), el.name() + (std::strlen(el.name()) - tag.size()));
      el.set_name((prefix + "path").c_str());
      el.append_attribute("d") = path_data(path, &points[first * 2], to_local, decimals).c_str();
    }
    for (pugi::xml_node a = el.child("animate"); a;) {  // replace an earlier fit's animation
      pugi::xml_node next = a.next_sibling("animate");
      if (std::string_view(a.attribute("attributeName").value()) == "d") el.remove_child(a);
      a = next;
    }
    pugi::xml_node anim = el.append_child("animate");
    anim.append_attribute("attributeName") = "d";
    anim.append_attribute("dur") = dur;
    if (timing.loop == LoopMode::Once) {
      anim.append_attribute("repeatCount") = "1";
      anim.append_attribute("fill") = "freeze";
    } else {
      anim.append_attribute("repeatCount") = "indefinite";
    }
    anim.append_attribute("calcMode") = "linear";
    anim.append_attribute("keyTimes") = key_times.c_str();
    anim.append_attribute("values") = values.c_str();
  }
  if (map && !map->order.empty()) {
    const ReorderResult r = reorder_elements(elements, scene, map->order);
    if (r.refused) throw Error(source.string() + ": cannot apply the paint order: " + *r.refused);
  }
  if (skipped_use)
    warnings.push_back(source.string() + ": " + std::to_string(skipped_use) +
                       " shapes drawn through <use> left static (shared definitions)");

  // Raw format with the parsed whitespace kept: the user's document comes back as they wrote
  // it, plus our <animate> children.
  write_file_atomic(out, with_original_prolog(original, static_cast<size_t>(std::max<ptrdiff_t>(1, root_name_at) - 1),
                                              doc.document_element()));
  return warnings;
}

}  // namespace svgm
