// The SMIL animation writer (see smil_writer.h).
#include "fit/smil_writer.h"
#include "svgmotion/atomic_file.h"

#include <pugixml.hpp>

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>


#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// Shortest round-trip text of a coordinate rounded to 1/1000 unit: compact, and well below
// a pixel at any sensible size.
void append_number(std::string& s, double v) {
  v = std::round(v * 1000.0) / 1000.0;
  if (v == 0) v = 0;  // no "-0"
  char buf[32];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, ec == std::errc() ? p : buf);
}

std::string_view local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

// Finds the element at a locator like "/svg/g[2]/rect[1]" (1-based among same-named
// siblings, names without namespace prefixes).
pugi::xml_node find_locator(pugi::xml_document& doc, const std::string& locator) {
  pugi::xml_node node = doc;
  std::string_view rest = locator;
  while (!rest.empty()) {
    if (rest.front() == '/') rest.remove_prefix(1);
    const size_t slash = rest.find('/');
    std::string_view part = rest.substr(0, slash);
    rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash);
    int index = 1;
    std::string_view name = part;
    if (const size_t br = part.find('['); br != std::string_view::npos) {
      name = part.substr(0, br);
      std::from_chars(part.data() + br + 1, part.data() + part.size() - 1, index);
    }
    pugi::xml_node found;
    int seen = 0;
    for (pugi::xml_node c = node.first_child(); c; c = c.next_sibling()) {
      if (c.type() == pugi::node_element && local_name(c.name()) == name && ++seen == index) {
        found = c;
        break;
      }
    }
    if (!found) return {};
    node = found;
  }
  return node;
}

constexpr const char* kShapeGeometry[] = {"x", "y", "width", "height", "rx", "ry", "cx",
                                          "cy", "r", "x1", "y1", "x2", "y2", "points"};

}  // namespace

std::string path_data(const Path& path, const double* cp, const Affine& to_local) {
  std::string d;
  for (const Subpath& sp : path.subpaths) {
    if (sp.points.empty()) continue;
    for (size_t i = 0; i < sp.points.size(); ++i) {
      const Vec2 q = to_local.apply({cp[2 * i], cp[2 * i + 1]});
      if (i == 0) d += d.empty() ? "M" : " M";
      else if (i % 3 == 1) d += " C";
      d += ' ';
      append_number(d, q.x);
      d += ' ';
      append_number(d, q.y);
    }
    if (sp.closed) d += " Z";
    cp += 2 * sp.points.size();
  }
  return d;
}

std::vector<std::string> write_animation_svg(const fs::path& source, const Scene& scene,
                                             const RasterPlan& plan,
                                             const std::vector<double>& points,
                                             const AnimationTiming& timing, const fs::path& out) {
  const int K = timing.keyframes;
  if (K < 1 || points.size() != static_cast<size_t>(K) * plan.n_cp * 2)
    throw Error("internal: animation points do not match the plan");
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_file(
      source.c_str(), pugi::parse_default | pugi::parse_ws_pcdata | pugi::parse_declaration |
                          pugi::parse_comments | pugi::parse_doctype | pugi::parse_pi);
  if (!parsed) throw Error(source.string() + ": cannot re-read for export: " + parsed.description());

  std::vector<std::string> warnings;
  std::string key_times;
  for (int k = 0; k < K; ++k) {
    if (k) key_times += ';';
    append_number(key_times, K > 1 ? static_cast<double>(k) / (K - 1) : 0.0);
  }
  char dur[32];
  std::snprintf(dur, sizeof dur, "%.3gs", timing.duration_s);
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
    if (plan.path_cp_count[p] == 0) continue;
    pugi::xml_node el = elements[p];
    const std::string_view tag = local_name(el.name());
    if (tag == "use") {
      ++skipped_use;
      continue;
    }
    const Affine to_local = path.to_canvas.inverse();
    std::string values;
    for (int k = 0; k < K; ++k) {
      if (k) values += ';';
      values += path_data(path, &points[(static_cast<size_t>(k) * plan.n_cp + plan.path_cp_first[p]) * 2], to_local);
    }
    if (tag != "path") {
      // Only <path> has a `d`: turn the shape into one, keeping id, paint and transform.
      for (const char* a : kShapeGeometry) el.remove_attribute(a);
      const std::string prefix(el.name(), el.name() + (std::strlen(el.name()) - tag.size()));
      el.set_name((prefix + "path").c_str());
      el.append_attribute("d") = path_data(path, &points[plan.path_cp_first[p] * 2], to_local).c_str();
    }
    for (pugi::xml_node a = el.child("animate"); a;) {  // replace an earlier fit's animation
      pugi::xml_node next = a.next_sibling("animate");
      if (std::string_view(a.attribute("attributeName").value()) == "d") el.remove_child(a);
      a = next;
    }
    pugi::xml_node anim = el.append_child("animate");
    anim.append_attribute("attributeName") = "d";
    anim.append_attribute("dur") = dur;
    anim.append_attribute("repeatCount") = "indefinite";
    anim.append_attribute("calcMode") = "linear";
    anim.append_attribute("keyTimes") = key_times.c_str();
    anim.append_attribute("values") = values.c_str();
  }
  if (skipped_use)
    warnings.push_back(source.string() + ": " + std::to_string(skipped_use) +
                       " shapes drawn through <use> left static (shared definitions)");

  // Raw format with the parsed whitespace kept: the user's document comes back as they wrote
  // it, plus our <animate> children.
  std::ostringstream text;
  doc.save(text, "", pugi::format_raw | pugi::format_no_declaration, pugi::encoding_utf8);
  write_file_atomic(out, text.str());
  return warnings;
}

}  // namespace svgm
