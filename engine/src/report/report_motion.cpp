// report.html's motion section (see report_motion.h).
#include "report/report_motion.h"

#include <set>
#include <vector>

#include "report/html_text.h"

namespace svgm {

namespace {

using nlohmann::json;

std::string str(const json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

std::vector<std::string> strings(const json& j, const char* key) {
  std::vector<std::string> out;
  if (j.is_object() && j.contains(key) && j[key].is_array())
    for (const json& s : j[key])
      if (s.is_string()) out.push_back(s.get<std::string>());
  return out;
}

std::string list(const std::vector<std::string>& items, const char* cls) {
  std::string s = std::string("<ul class=\"") + cls + "\">";
  for (const auto& i : items) s += "<li>" + html_escape(i) + "</li>";
  return s + "</ul>";
}

// The names of the parts an action moves ("whole figure", "12 repeated elements", or names).
std::vector<std::string> moved_parts(const json& action) {
  std::vector<std::string> out;
  if (!action.contains("parts")) return out;
  const json& p = action["parts"];
  if (p.is_string()) out.push_back(p.get<std::string>());
  else if (p.is_array())
    for (const json& n : p)
      if (n.is_string()) out.push_back(n.get<std::string>());
  return out;
}

// The drawing with every moving part's box outlined and named (canvas units: motion.json's
// boxes are the rig's, in the scene's canvas space).
std::string outlines(const json& motion, const std::string& drawing_uri) {
  if (drawing_uri.empty() || !motion.contains("canvas") || !motion["canvas"].is_array() || motion["canvas"].size() != 2 ||
      !motion["canvas"][0].is_number() || !motion["canvas"][1].is_number())
    return "";
  const double W = motion["canvas"][0].get<double>(), H = motion["canvas"][1].get<double>();
  if (!(W > 0) || !(H > 0)) return "";
  std::set<std::string> moving;
  bool whole = false;
  if (motion.contains("plan") && motion["plan"].is_array())
    for (const json& a : motion["plan"])
      for (const auto& n : moved_parts(a)) {
        moving.insert(n);
        whole = whole || n == "whole figure";
      }
  const double stroke = 0.006 * std::max(W, H), font = 0.035 * std::max(W, H);
  std::string s = "<svg class=\"svgm-motion-parts\" width=\"320\" viewBox=\"0 0 " + html_number(W, 8) + " " + html_number(H, 8) +
                  "\" role=\"img\" aria-label=\"the parts that move\"><image href=\"" + drawing_uri + "\" width=\"" +
                  html_number(W, 8) + "\" height=\"" + html_number(H, 8) + "\" opacity=\"0.55\"/>";
  if (motion.contains("parts") && motion["parts"].is_array())
    for (const json& p : motion["parts"]) {
      const std::string name = str(p, "name");
      if (!whole && !moving.count(name)) continue;
      if (!p.contains("box") || !p["box"].is_array() || p["box"].size() != 4) continue;
      double b[4];
      bool ok = true;
      for (int i = 0; i < 4; ++i) ok = ok && p["box"][i].is_number() && ((b[i] = p["box"][i].get<double>()), true);
      if (!ok || b[2] < b[0] || b[3] < b[1]) continue;
      if (whole && str(p, "role") == "background") continue;
      s += "<rect x=\"" + html_number(b[0], 8) + "\" y=\"" + html_number(b[1], 8) + "\" width=\"" + html_number(b[2] - b[0], 8) +
           "\" height=\"" + html_number(b[3] - b[1], 8) + "\" fill=\"none\" stroke=\"#d00\" stroke-width=\"" + html_number(stroke, 4) +
           "\"/><text x=\"" + html_number(b[0], 8) + "\" y=\"" + html_number(std::max(font, b[1] - stroke), 8) + "\" font-size=\"" +
           html_number(font, 4) + "\" fill=\"#d00\">" + html_escape(name) + "</text>";
    }
  return s + "</svg>";
}

}  // namespace

std::string motion_section(const json& motion, const std::string& drawing_uri) {
  std::string s = "<section id=\"svgm-motion\"><h2>The motion</h2>";
  if (!motion.is_object()) return s + "<p>No motion.json: the target video did not come from the prompt's words.</p></section>\n";
  const std::string source = str(motion, "source");
  s += "<p>Planned from " + html_escape(source == "prompt" ? "the prompt" : source.empty() ? "?" : source);
  if (motion.contains("keyframes") && motion["keyframes"].is_number_integer() && motion["keyframes"].get<int>() > 0)
    s += "; the fitter follows it with " + html_escape(std::to_string(motion["keyframes"].get<int>())) + " keyframes";
  s += ".</p><div class=\"svgm-row\">" + outlines(motion, drawing_uri) + "<table class=\"svgm-plan\"><tr><th>verb</th><th>motion</th>"
       "<th>parts</th><th>amplitude</th><th>cycles</th><th>why</th></tr>";
  if (motion.contains("plan") && motion["plan"].is_array())
    for (const json& a : motion["plan"]) {
      std::string parts;
      for (const auto& n : moved_parts(a)) parts += (parts.empty() ? "" : ", ") + n;
      std::string amp = a.contains("amplitude") && a["amplitude"].is_number() ? html_number(a["amplitude"].get<double>(), 3) : "-";
      amp += " " + html_escape(str(a, "unit"));
      if (a.contains("one_sided") && a["one_sided"].is_number_integer() && a["one_sided"].get<int>() != 0) amp += ", one side only";
      const std::string region = str(a, "region");
      s += "<tr><td>" + html_escape(str(a, "verb")) + "</td><td>" + html_escape(str(a, "motion")) +
           (region.empty() ? "" : " (" + html_escape(region) + ")") + "</td><td>" + html_escape(parts) + "</td><td>" + amp +
           "</td><td>" + (a.contains("cycles") && a["cycles"].is_number() ? html_number(a["cycles"].get<double>(), 3) : "-") +
           "</td><td>" + html_escape(str(a, "why")) + "</td></tr>";
    }
  s += "</table></div>";
  const auto not_understood = strings(motion, "not_understood"), warnings = strings(motion, "warnings"), notes = strings(motion, "notes"),
             readings = strings(motion, "readings");
  if (!readings.empty()) s += "<p>Words read through the lexicon (WordNet):</p>" + list(readings, "svgm-readings");
  if (!not_understood.empty()) s += "<p class=\"svgm-warn\">Words not understood:</p>" + list(not_understood, "svgm-not-understood");
  if (!warnings.empty()) s += "<p class=\"svgm-warn\">Warnings:</p>" + list(warnings, "svgm-motion-warnings");
  if (!notes.empty()) s += "<p>Notes:</p>" + list(notes, "svgm-motion-notes");
  return s + "</section>\n";
}

}  // namespace svgm
