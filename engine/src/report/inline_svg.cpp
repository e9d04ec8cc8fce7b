// The user's animation rebuilt from an allow-list for report.html (see inline_svg.h).
#include "report/inline_svg.h"

#include <pugixml.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include "report/drop_tally.h"
#include "report/safe_css.h"
#include "svgmotion/error.h"

namespace svgm {

namespace {

constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";
constexpr std::string_view kXlinkNamespace = "http://www.w3.org/1999/xlink";
// Deeper elements are dropped (and counted): the sanitiser recurses, and the renderer refuses to
// draw deeper ones anyway (SvgReadLimits::max_depth).
constexpr int kMaxDepth = 256;
// The box report.html inlines the animation into: its style sheets apply inside it only.
constexpr std::string_view kScope = "#svgm-stage ";

// What a kept element may hold. Text: characters only (title and desc are HTML integration
// points, where an HTML parser would read child tags as HTML). Mixed: characters and elements
// (text, tspan). Style: a style sheet. Elements: elements only (characters between them are not
// drawn, so they go without a word).
enum class Holds { Elements, Text, Mixed, Style };

struct ElementRule {
  std::string_view name;  // as SVG spells it; HTML's parser gives the camelCase ones this case
  Holds holds = Holds::Elements;
  bool href = false;      // may refer to an element of the document by href="#id"
  bool needs_href = false;  // is nothing without that reference (use, mpath)
  bool animation = false;   // sets an attribute by attributeName
};

constexpr std::array<ElementRule, 29> kElements = {{
    {"svg"}, {"g"}, {"defs"}, {"symbol"}, {"switch"}, {"a"},
    {"use", Holds::Elements, true, true},
    {"path"}, {"rect"}, {"circle"}, {"ellipse"}, {"line"}, {"polyline"}, {"polygon"},
    {"linearGradient", Holds::Elements, true}, {"radialGradient", Holds::Elements, true}, {"stop"},
    {"clipPath"}, {"mask"},
    {"style", Holds::Style}, {"title", Holds::Text}, {"desc", Holds::Text},
    {"text", Holds::Mixed}, {"tspan", Holds::Mixed},
    {"animate", Holds::Elements, true, false, true}, {"animateTransform", Holds::Elements, true, false, true},
    {"set", Holds::Elements, true, false, true}, {"animateMotion", Holds::Elements, true},
    {"mpath", Holds::Elements, true, true},
}};

// Attributes whose value is geometry, a number list, a keyword or SMIL timing: nothing in them
// is a URL or is run, so they are kept as written (escaped).
const std::set<std::string_view> kPlainAttributes = {
    "class", "transform", "d", "x", "y", "width", "height", "rx", "ry", "cx", "cy", "r", "fx", "fy",
    "fr", "x1", "y1", "x2", "y2", "dx", "dy", "rotate", "points", "pathLength", "viewBox",
    "preserveAspectRatio", "offset", "gradientUnits", "gradientTransform", "spreadMethod",
    "clipPathUnits", "maskUnits", "maskContentUnits", "systemLanguage", "requiredFeatures",
    "requiredExtensions", "attributeName", "attributeType", "type", "values", "from", "to", "by",
    "keyTimes", "keySplines", "keyPoints", "calcMode", "dur", "begin", "end", "repeatCount",
    "repeatDur", "additive", "accumulate", "restart", "min", "max", "path", "version", "xml:space"};

// What an animation element may set besides the CSS properties (safe_css_property): geometry.
const std::set<std::string_view> kAnimatedGeometry = {
    "d", "transform", "gradientTransform", "points", "x", "y", "width", "height", "rx", "ry", "cx", "cy",
    "r", "fx", "fy", "x1", "y1", "x2", "y2", "dx", "dy", "offset", "pathLength"};

const ElementRule* rule_of(std::string_view local) {
  for (const ElementRule& r : kElements)
    if (r.name == local) return &r;
  return nullptr;
}

bool has_markup(std::string_view text) { return text.find_first_of("<>") != std::string_view::npos; }

// A name for the warning line: as written, cut short (it is printed and shown on the page).
std::string shown(std::string_view name) {
  return name.size() > 40 ? std::string(name.substr(0, 40)) + "..." : std::string(name);
}

void escape_into(std::string& out, std::string_view s) {
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      // XML normalises whitespace characters in attribute values to spaces, HTML keeps them:
      // as references both keep them.
      case '\t': out += "&#9;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      default: out += c;
    }
  }
}

// A length in user units: a plain number or px; anything else (%, mm, em) has no plain size.
bool user_units(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  if (end == text || !(out > 0)) return false;
  const std::string_view rest(end);
  return rest.empty() || rest == "px";
}

class Sanitiser {
 public:
  explicit Sanitiser(DropTally& dropped) : dropped_(dropped) {}

  void root(pugi::xml_node n, std::string& out) {
    std::string vb;
    double w = 0, h = 0;
    if (!n.attribute("viewBox") && user_units(n.attribute("width").value(), w) &&
        user_units(n.attribute("height").value(), h)) {
      std::ostringstream s;
      s << "0 0 " << w << " " << h;
      vb = s.str();
    }
    out += "<svg xmlns=\"";
    out += kSvgNamespace;
    out += "\"";
    if (!vb.empty()) out += " viewBox=\"" + vb + "\"";
    out += " width=\"100%\" height=\"100%\"";
    attributes(n, *rule_of("svg"), true, out);
    out += ">";
    children(n, Holds::Elements, 0, out);
    out += "</svg>";
  }

 private:
  // The namespace bound to `prefix` ("" for the default one) where `n` is, if any.
  static std::optional<std::string_view> namespace_of(pugi::xml_node n, std::string_view prefix) {
    const std::string decl = prefix.empty() ? "xmlns" : "xmlns:" + std::string(prefix);
    for (pugi::xml_node p = n; p && p.type() == pugi::node_element; p = p.parent())
      if (const pugi::xml_attribute a = p.attribute(decl.c_str())) return std::string_view(a.value());
    return std::nullopt;
  }

  // The element's local name when it is in the SVG namespace. An undeclared default namespace
  // or "svg:" prefix counts as SVG, as svgmotion's reader takes them.
  static std::optional<std::string_view> svg_local_name(pugi::xml_node n) {
    const std::string_view name = n.name();
    const size_t colon = name.find(':');
    const std::string_view prefix = colon == std::string_view::npos ? std::string_view() : name.substr(0, colon);
    const std::string_view local = colon == std::string_view::npos ? name : name.substr(colon + 1);
    const auto ns = namespace_of(n, prefix);
    if (ns ? *ns == kSvgNamespace : (prefix.empty() || prefix == "svg")) return local;
    return std::nullopt;
  }

  void element(pugi::xml_node n, int depth, std::string& out) {
    const auto local = svg_local_name(n);
    const ElementRule* rule = local ? rule_of(*local) : nullptr;
    if (!rule) {
      dropped_.add("<" + shown(n.name()) + ">");
      return;
    }
    const std::string tag(rule->name);
    if (rule->needs_href && !local_reference(href_of(n))) {
      dropped_.add("<" + tag + "> with an href outside the drawing", "<" + tag + "> with hrefs outside the drawing");
      return;
    }
    if (rule->animation) {
      // SMIL that sets an href to javascript:, an on* attribute or a style is script.
      const std::string_view target = n.attribute("attributeName").value();
      const bool css = safe_css_property(target);
      if (!target.empty() && !css && !kAnimatedGeometry.count(target)) {
        dropped_.add("<" + tag + "> of " + shown(target), "<" + tag + "> of " + shown(target));
        return;
      }
      if (css)
        for (const char* a : {"values", "from", "to", "by"}) {
          const std::string_view v = n.attribute(a).value();
          bool safe = true;
          for (size_t at = 0; at <= v.size() && safe;) {
            const size_t semi = std::min(v.find(';', at), v.size());
            safe = safe_css_value(v.substr(at, semi - at));
            at = semi + 1;
          }
          if (!safe) {
            dropped_.add("<" + tag + "> with an unsafe value", "<" + tag + "> with unsafe values");
            return;
          }
        }
    }
    out += "<" + tag;
    attributes(n, *rule, false, out);
    out += ">";
    children(n, rule->holds, depth, out);
    out += "</" + tag + ">";
  }

  // The element's href or xlink:href, whichever it has ("" if none).
  static std::string_view href_of(pugi::xml_node n) {
    for (const pugi::xml_attribute a : n.attributes())
      if (is_href(n, a.name())) return a.value();
    return {};
  }

  static bool is_href(pugi::xml_node n, std::string_view name) {
    if (name == "href") return true;
    if (name.substr(name.find(':') + 1) != "href" || name.find(':') == std::string_view::npos) return false;
    const std::string_view prefix = name.substr(0, name.find(':'));
    const auto ns = namespace_of(n, prefix);
    return ns ? *ns == kXlinkNamespace : prefix == "xlink";
  }

  void attributes(pugi::xml_node n, const ElementRule& rule, bool root, std::string& out) {
    std::set<std::string> written;
    for (const pugi::xml_attribute a : n.attributes()) {
      const std::string_view name = a.name(), value = a.value();
      // Namespace declarations: the markup is written in the SVG namespace, with no prefixes.
      if (name == "xmlns" || name.substr(0, 6) == "xmlns:") continue;
      if (root && (name == "width" || name == "height")) continue;  // 100%, written by root()
      std::string kept_name(name);
      std::string kept_value(value);
      if (name.size() >= 2 && (name[0] == 'o' || name[0] == 'O') && (name[1] == 'n' || name[1] == 'N')) {
        dropped_.add("on* attribute", "on* attributes");
        continue;
      } else if (is_href(n, name)) {
        if (!local_reference(value)) {
          dropped_.add("href outside the drawing", "hrefs outside the drawing");
          continue;
        }
        if (!rule.href) {
          dropped_.add("href on <" + std::string(rule.name) + ">", "hrefs on <" + std::string(rule.name) + ">");
          continue;
        }
        kept_name = "href";  // SVG 2's href: no xlink namespace to declare
      } else if (name == "id") {
        // The page's own elements are found by id (svgm-play, svgm-scrub ...).
        if (value.substr(0, 5) == "svgm-") {
          dropped_.add("id taken from the page (svgm-...)", "ids taken from the page (svgm-...)");
          continue;
        }
      } else if (name == "style") {
        kept_value = safe_style_declarations(value, dropped_);
        if (kept_value.empty()) continue;
      } else if (safe_css_property(name)) {
        if (!safe_css_value(value)) {
          dropped_.add(shown(name) + " attribute with an unsafe value", shown(name) + " attributes with unsafe values");
          continue;
        }
      } else if (name.substr(0, 5) == "data-" && name.size() > 5 &&
                 std::all_of(name.begin() + 5, name.end(), [](char c) {
                   return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
                 })) {
        // data-group, data-name (svgmotion's own part names): inert.
      } else if (!kPlainAttributes.count(name)) {
        const size_t colon = name.find(':');
        const std::string kind = colon == std::string_view::npos ? shown(name) : shown(name.substr(0, colon)) + ":*";
        dropped_.add(kind + " attribute", kind + " attributes");
        continue;
      }
      if (!written.insert(kept_name).second) continue;  // a second href, or a repeated name
      out += " " + kept_name + "=\"";
      escape_into(out, kept_value);
      out += "\"";
    }
  }

  void children(pugi::xml_node n, Holds holds, int depth, std::string& out) {
    std::string css;
    for (const pugi::xml_node c : n.children()) {
      switch (c.type()) {
        case pugi::node_element:
          if (holds == Holds::Elements || holds == Holds::Mixed) {
            if (depth + 1 > kMaxDepth)
              dropped_.add("element nested deeper than " + std::to_string(kMaxDepth),
                           "elements nested deeper than " + std::to_string(kMaxDepth));
            else
              element(c, depth + 1, out);
          } else {
            dropped_.add("<" + shown(c.name()) + "> inside <" + shown(n.name()) + ">");
          }
          break;
        case pugi::node_pcdata:
          if (holds == Holds::Style) css += c.value();
          else if (holds != Holds::Elements) escape_into(out, c.value());
          break;
        case pugi::node_cdata:
          // Outside a style sheet CDATA is text to XML but markup to HTML where it is not foreign.
          if (holds == Holds::Style) css += c.value();
          else if (holds != Holds::Elements && !has_markup(c.value())) escape_into(out, c.value());
          else if (has_markup(c.value())) dropped_.add("CDATA section holding markup", "CDATA sections holding markup");
          break;
        case pugi::node_comment:
          // Comments never change the picture; those with markup are how "<!-->" attacks look.
          if (has_markup(c.value())) dropped_.add("comment holding markup", "comments holding markup");
          break;
        case pugi::node_pi:
          dropped_.add("<?" + shown(c.name()) + "?>");
          break;
        default:
          break;
      }
    }
    if (holds == Holds::Style) escape_into(out, safe_style_sheet(css, kScope, dropped_));
  }

  DropTally& dropped_;
};

}  // namespace

InlinedSvg inline_svg(const std::filesystem::path& file) {
  pugi::xml_document doc;
  const pugi::xml_parse_result r =
      doc.load_file(file.c_str(), pugi::parse_default | pugi::parse_comments | pugi::parse_pi | pugi::parse_doctype);
  if (!r) throw Error(file.string() + ": not an SVG document (" + r.description() + ")");
  pugi::xml_node root = doc.document_element();
  const std::string_view root_name = root.name();
  if (root_name.substr(root_name.find(':') + 1) != "svg")
    throw Error(file.string() + ": not an SVG document (no <svg> root)");
  DropTally dropped;
  // Before and after the root: the XML declaration and plain comments go without a word.
  for (const pugi::xml_node c : doc.children()) {
    if (c.type() == pugi::node_pi) dropped.add("<?" + shown(c.name()) + "?>");
    else if (c.type() == pugi::node_doctype && std::strchr(c.value(), '['))
      dropped.add("DOCTYPE with declarations (entities)", "DOCTYPEs with declarations (entities)");
    else if (c.type() == pugi::node_comment && has_markup(c.value()))
      dropped.add("comment holding markup", "comments holding markup");
  }
  InlinedSvg out;
  Sanitiser(dropped).root(root, out.markup);
  out.dropped = dropped.summary();
  return out;
}

}  // namespace svgm
