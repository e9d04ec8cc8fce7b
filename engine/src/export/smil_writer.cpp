// The SMIL animation writer (see smil_writer.h): one pass of the animation, path data and the
// checks every writer makes, and the helpers the full (smil_full_writer.cpp) and the compact
// (smil_compact_writer.cpp) export share (smil_writer_internal.h).
#include "export/smil_writer.h"

#include <pugixml.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "export/smil_writer_internal.h"
#include "svg/document_order.h"
#include "svg/svg_number.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace smil_internal {

void append_number(std::string& s, double v, int decimals) {
  svg::append_rounded(s, v, std::pow(10.0, decimals));
}

std::string_view local_name(const char* name) {
  const char* colon = std::strchr(name, ':');
  return colon ? std::string_view(colon + 1) : std::string_view(name);
}

std::string with_original_prolog(const std::string& original, size_t root_begin, pugi::xml_node root) {
  const std::string close = std::string("</") + root.name();
  size_t root_end = original.rfind(close);
  if (root_end != std::string::npos) root_end = original.find('>', root_end);
  std::ostringstream body;
  root.print(body, "", pugi::format_raw, pugi::encoding_utf8);
  if (root_end == std::string::npos || root_end < root_begin) return body.str();
  return original.substr(0, root_begin) + body.str() + original.substr(root_end + 1);
}

double rounded(double v, int decimals) {
  const double f = std::pow(10.0, decimals);
  const double r = std::round(v * f) / f;
  return r == 0 ? 0.0 : r;  // no "-0"
}

ptrdiff_t reread_source(const fs::path& source, std::string& original, pugi::xml_document& doc) {
  std::ifstream in(source, std::ios::binary);
  original.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw Error(source.string() + ": cannot re-read for export");
  const pugi::xml_parse_result parsed = doc.load_buffer(original.data(), original.size(), kKeepDocumentParse);
  if (!parsed) throw Error(source.string() + ": cannot re-read for export: " + parsed.description());
  return doc.document_element().offset_debug();
}

std::vector<pugi::xml_node> find_elements(pugi::xml_document& doc, const Scene& scene, const fs::path& source) {
  std::vector<pugi::xml_node> elements;
  for (const Path& path : scene.paths) {
    elements.push_back(find_locator(doc, path.locator));
    if (!elements.back()) throw Error("internal: " + path.locator + " not found in " + source.string());
  }
  return elements;
}

void remove_gradient_animations(pugi::xml_node gn) {
  for (pugi::xml_node a = gn.first_child(); a;) {
    pugi::xml_node next = a.next_sibling();
    if (local_name(a.name()) == "animateTransform" &&
        std::string_view(a.attribute("attributeName").value()) == "gradientTransform")
      gn.remove_child(a);
    a = next;
  }
}

void append_repeat(pugi::xml_node anim, const char* dur, LoopMode loop) {
  anim.append_attribute("dur") = dur;
  if (loop == LoopMode::Once) {
    anim.append_attribute("repeatCount") = "1";
    anim.append_attribute("fill") = "freeze";
  } else {
    anim.append_attribute("repeatCount") = "indefinite";
  }
}

}  // namespace smil_internal

using namespace smil_internal;

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

}  // namespace svgm
