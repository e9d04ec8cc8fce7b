// An SVG document made fit to inline into report.html (see inline_svg.h).
#include "report/inline_svg.h"

#include <pugixml.hpp>

#include <cstdlib>
#include <sstream>
#include <string_view>
#include <vector>

#include "svgmotion/error.h"

namespace svgm {

namespace {

bool starts_with_nocase(std::string_view s, std::string_view prefix) {
  size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
  s.remove_prefix(i);
  if (s.size() < prefix.size()) return false;
  for (size_t k = 0; k < prefix.size(); ++k)
    if (std::tolower(static_cast<unsigned char>(s[k])) != prefix[k]) return false;
  return true;
}

std::string_view local_name(std::string_view name) {
  const size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

void strip_active_content(pugi::xml_node node) {
  std::vector<pugi::xml_node> drop;
  for (pugi::xml_node child : node.children()) {
    if (child.type() == pugi::node_element && local_name(child.name()) == "script") drop.push_back(child);
    else if (child.type() == pugi::node_element) strip_active_content(child);
  }
  for (pugi::xml_node d : drop) node.remove_child(d);
  std::vector<pugi::xml_attribute> bad;
  for (pugi::xml_attribute a : node.attributes()) {
    const std::string_view n = a.name();
    if (starts_with_nocase(n, "on") || (local_name(n) == "href" && starts_with_nocase(a.value(), "javascript:")))
      bad.push_back(a);
  }
  for (pugi::xml_attribute a : bad) node.remove_attribute(a);
}

// A length in user units: a plain number or px; anything else (%, mm, em) has no plain size.
bool user_units(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  if (end == text || !(out > 0)) return false;
  const std::string_view rest(end);
  return rest.empty() || rest == "px";
}

}  // namespace

std::string inline_svg(const std::filesystem::path& file) {
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_file(file.c_str(), pugi::parse_default | pugi::parse_comments);
  if (!r) throw Error(file.string() + ": not an SVG document (" + r.description() + ")");
  pugi::xml_node root = doc.document_element();
  if (local_name(root.name()) != "svg") throw Error(file.string() + ": not an SVG document (no <svg> root)");
  strip_active_content(root);
  double w = 0, h = 0;
  if (!root.attribute("viewBox") && user_units(root.attribute("width").value(), w) &&
      user_units(root.attribute("height").value(), h)) {
    std::ostringstream vb;
    vb << "0 0 " << w << " " << h;
    root.append_attribute("viewBox") = vb.str().c_str();
  }
  for (const char* a : {"width", "height"}) {
    if (!root.attribute(a)) root.append_attribute(a);
    root.attribute(a) = "100%";
  }
  std::ostringstream out;
  root.print(out, "", pugi::format_raw);
  return out.str();
}

}  // namespace svgm
