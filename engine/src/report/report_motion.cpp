// report.html's motion section (see report_motion.h).
#include "report/report_motion.h"

#include <algorithm>
#include <cmath>
#include <optional>
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

std::string join(const std::vector<std::string>& items, const char* sep) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : sep) + i;
  return s;
}

std::string list(const std::vector<std::string>& items, const char* cls) {
  std::string s = std::string("<ul class=\"") + cls + "\">";
  for (const auto& i : items) s += "<li>" + html_escape(i) + "</li>";
  return s + "</ul>";
}

const json& plan_of(const json& motion) {
  static const json none = json::array();
  return motion.is_object() && motion.contains("plan") && motion["plan"].is_array() ? motion["plan"] : none;
}

// The plan is plan_from_prompt's gentle sway because no motion word was understood. motion.json
// says so per action ("fallback"); one written before that field says it in its warning.
bool is_fallback(const json& motion) {
  for (const json& a : plan_of(motion))
    if (a.is_object() && a.value("fallback", false) == true) return true;
  for (const auto& w : strings(motion, "warnings"))
    if (w.rfind("no motion understood in the prompt", 0) == 0) return true;
  return false;
}

// The words the plan did not understand. A word the lexicon read ("'man': biped, ...": a figure's
// class, motion.json's "readings") is listed by the plan when it names no part of the drawing;
// the page shows it with its reading instead, not as a word nothing understood.
std::vector<std::string> not_understood(const json& motion) {
  const auto readings = strings(motion, "readings");
  std::vector<std::string> out;
  for (const auto& w : strings(motion, "not_understood"))
    if (std::none_of(readings.begin(), readings.end(), [&](const std::string& r) { return r.rfind("'" + w + "':", 0) == 0; }))
      out.push_back(w);
  return out;
}

// One colour per action, for its row and its outlines: far apart in hue and dark enough to read
// on white and over the drawing (Tableau 10's first eight).
constexpr const char* kActionColours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd",
                                          "#ff7f0e", "#17becf", "#e377c2", "#8c564b"};
const char* colour_of(size_t action) { return kActionColours[action % std::size(kActionColours)]; }

// The names of the parts an action moves ("whole figure", "12 repeated elements", or names).
std::vector<std::string> moved_parts(const json& action) {
  std::vector<std::string> out;
  if (!action.is_object() || !action.contains("parts")) return out;
  const json& p = action["parts"];
  if (p.is_string()) out.push_back(p.get<std::string>());
  else if (p.is_array())
    for (const json& n : p)
      if (n.is_string()) out.push_back(n.get<std::string>());
  return out;
}

struct Box {
  double x0, y0, x1, y1;
};

std::optional<Box> box_of(const json& part) {
  if (!part.is_object() || !part.contains("box") || !part["box"].is_array() || part["box"].size() != 4) return std::nullopt;
  double b[4];
  for (int i = 0; i < 4; ++i) {
    if (!part["box"][i].is_number()) return std::nullopt;
    b[i] = part["box"][i].get<double>();
  }
  if (!std::isfinite(b[0] + b[1] + b[2] + b[3]) || b[2] < b[0] || b[3] < b[1]) return std::nullopt;
  return Box{b[0], b[1], b[2], b[3]};
}

const json* part_named(const json& motion, const std::string& name) {
  if (motion.contains("parts") && motion["parts"].is_array())
    for (const json& p : motion["parts"])
      if (str(p, "name") == name) return &p;
  return nullptr;
}

// The figure: every part but the background (what "whole figure" moves).
std::optional<Box> figure_box(const json& motion) {
  std::optional<Box> f;
  if (motion.contains("parts") && motion["parts"].is_array())
    for (const json& p : motion["parts"]) {
      const auto b = box_of(p);
      if (!b || str(p, "role") == "background") continue;
      f = f ? Box{std::min(f->x0, b->x0), std::min(f->y0, b->y0), std::max(f->x1, b->x1), std::max(f->y1, b->y1)} : *b;
    }
  return f;
}

// The boxes action `a` moves: the figure's, or each named part's (the part a region bends in).
std::vector<Box> action_boxes(const json& motion, const json& a) {
  std::vector<Box> out;
  const auto names = moved_parts(a);
  if (a.contains("parts") && a["parts"].is_string()) {
    if (names[0] == "whole figure")
      if (const auto f = figure_box(motion)) out.push_back(*f);
    return out;  // repeated elements: motion.json names no boxes for them
  }
  for (const auto& n : names)
    if (const json* p = part_named(motion, n))
      if (const auto b = box_of(*p)) out.push_back(*b);
  return out;
}

// The drawing in its own colours with each action's parts outlined in the action's colour and
// numbered as its row is (canvas units: motion.json's boxes are the rig's, in the scene's canvas
// space). Each action's boxes stand a little farther out than the one before, so two actions on
// one part both show.
std::string outlines(const json& motion, const std::string& drawing_uri) {
  if (drawing_uri.empty() || !motion.contains("canvas") || !motion["canvas"].is_array() || motion["canvas"].size() != 2 ||
      !motion["canvas"][0].is_number() || !motion["canvas"][1].is_number())
    return "";
  const double W = motion["canvas"][0].get<double>(), H = motion["canvas"][1].get<double>();
  if (!(W > 0) || !(H > 0) || !std::isfinite(W) || !std::isfinite(H)) return "";
  const double stroke = 0.008 * std::max(W, H), tag = 0.06 * std::max(W, H);
  auto n = [](double v) { return html_number(v, 8); };
  std::string s = "<svg class=\"svgm-motion-parts\" width=\"260\" viewBox=\"0 0 " + n(W) + " " + n(H) +
                  "\" role=\"img\" aria-label=\"the parts each action moves, outlined in its colour\"><image href=\"" +
                  drawing_uri + "\" width=\"" + n(W) + "\" height=\"" + n(H) + "\" opacity=\"0.7\"/>";
  const json& plan = plan_of(motion);
  for (size_t k = 0; k < plan.size(); ++k) {
    const std::string c = colour_of(k), number = std::to_string(k + 1);
    const bool region = !str(plan[k], "region").empty();
    const double out = stroke * 1.5 * static_cast<double>(k);
    for (const Box& b : action_boxes(motion, plan[k])) {
      const double x = b.x0 - out, y = b.y0 - out;
      s += "<rect class=\"svgm-outline\" data-action=\"" + number + "\" x=\"" + n(x) + "\" y=\"" + n(y) + "\" width=\"" +
           n(b.x1 - b.x0 + 2 * out) + "\" height=\"" + n(b.y1 - b.y0 + 2 * out) + "\" fill=\"none\" stroke=\"" + c +
           "\" stroke-width=\"" + html_number(stroke, 4) + "\"" +
           (region ? " stroke-dasharray=\"" + html_number(3 * stroke, 4) + "\"" : "") + "/>";
      // The number in a tag at the box's corner, kept on the canvas.
      const double tx = std::clamp(x, 0.0, W - tag), ty = std::clamp(y, 0.0, H - tag);
      s += "<rect x=\"" + n(tx) + "\" y=\"" + n(ty) + "\" width=\"" + n(tag) + "\" height=\"" + n(tag) + "\" fill=\"" + c +
           "\"/><text x=\"" + n(tx + tag / 2) + "\" y=\"" + n(ty + tag * 0.78) + "\" font-size=\"" + html_number(tag * 0.8, 4) +
           "\" text-anchor=\"middle\" fill=\"#fff\" font-family=\"sans-serif\">" + number + "</text>";
    }
  }
  return s + "</svg>";
}

// The amplitude as a reader measures it: rotations in degrees, turns as turns, sizes and
// distances in % of what they are a share of.
std::string amplitude_text(const json& a) {
  if (!a.contains("amplitude") || !a["amplitude"].is_number()) return "-";
  const double v = a["amplitude"].get<double>();
  const std::string unit = str(a, "unit");
  static const struct {
    const char* unit;
    const char* of;
  } kShares[] = {{"figure heights", "% of the figure's height"}, {"figure widths", "% of the figure's width"},
                 {"figure lengths", "% of the figure's length"}, {"canvas heights", "% of the canvas height"},
                 {"fraction of size", "% of its size"}};
  std::string s;
  for (const auto& k : kShares)
    if (unit == k.unit) s = html_number(v * 100, 3) + " " + html_escape(k.of);
  if (s.empty()) s = html_number(v, 3) + " " + html_escape(unit == "degrees" ? "\xC2\xB0" : unit);
  if (a.contains("one_sided") && a["one_sided"].is_number_integer() && a["one_sided"].get<int>() != 0) s += ", one side only";
  return s;
}

}  // namespace

MotionCaveat motion_caveat(const json& motion) {
  if (!motion.is_object()) return {};
  const auto unknown = not_understood(motion);
  if (is_fallback(motion))
    return {true, "no motion word in the prompt was understood" + (unknown.empty() ? std::string() : " (" + join(unknown, ", ") + ")") +
                      ": the figure only sways gently, a fallback"};
  if (!unknown.empty())
    return {false, std::string(unknown.size() > 1 ? "words" : "a word") + " of the prompt not understood: " + join(unknown, ", ") +
                       "; the motion follows the rest"};
  return {};
}

std::string motion_section(const json& motion, const std::string& drawing_uri) {
  std::string s = "<section id=\"svgm-motion\"><h2>The motion</h2>";
  if (!motion.is_object()) return s + "<p>No motion.json: the target video did not come from the prompt's words.</p></section>\n";
  const std::string source = str(motion, "source"), prompt = str(motion, "prompt");
  // The procedural video's llm planner (motion.json "planner"): whose plan it is, or why not.
  const json planner = motion.contains("planner") && motion["planner"].is_object() ? motion["planner"] : json::object();
  s += "<p>Planned from " + html_escape(source == "prompt" ? "the prompt" : source == "llm" ? "a vision model's plan (planner llm"
                                        + (str(planner, "model").empty() ? "" : ", " + str(planner, "model")) + ") for"
                                        : source.empty() ? "?" : source);
  if (!prompt.empty()) s += " <q class=\"svgm-motion-prompt\">" + html_escape(prompt) + "</q>";
  if (motion.contains("keyframes") && motion["keyframes"].is_number_integer() && motion["keyframes"].get<int>() > 0)
    s += "; the fitter follows it with " + html_escape(std::to_string(motion["keyframes"].get<int>())) + " keyframes";
  s += ".</p>";
  if (source == "llm" && !str(planner, "plan").empty())
    s += "<p>Its plan: <code class=\"svgm-llm-plan\">" + html_escape(str(planner, "plan")) + "</code></p>";
  if (!str(planner, "fallback").empty())
    s += "<p class=\"svgm-warn\" id=\"svgm-planner-fallback\">The llm planner gave no plan (" + html_escape(str(planner, "fallback")) +
         "): planned offline from the prompt's words.</p>";
  if (is_fallback(motion))
    s += "<p class=\"svgm-warn\" id=\"svgm-fallback\">No motion word in the prompt was understood: the figure only sways "
         "gently (a fallback, not what the prompt asked). Say the motion with a verb such as wave, walk, hop, spin or flap.</p>";
  const auto unknown = not_understood(motion), warnings = strings(motion, "warnings"), notes = strings(motion, "notes"),
             readings = strings(motion, "readings");
  if (!unknown.empty())
    s += "<p class=\"svgm-warn\" id=\"svgm-not-understood\">Not understood: " + html_escape(join(unknown, ", ")) +
         " <small>(the words the motion vocabulary and the lexicon do not know)</small></p>";
  s += "<div class=\"svgm-row\">" + outlines(motion, drawing_uri) +
       "<table class=\"svgm-plan\"><tr><th>#</th><th>verb</th><th>parts it moves</th><th>amplitude</th><th>direction</th>"
       "<th>cycles</th><th>why these parts</th></tr>";
  const json& plan = plan_of(motion);
  for (size_t k = 0; k < plan.size(); ++k) {
    const json& a = plan[k];
    std::string parts = html_escape(join(moved_parts(a), ", "));
    const std::string region = str(a, "region");
    if (!region.empty()) parts = "the " + html_escape(region) + " of " + parts;
    const std::string motion_kind = str(a, "motion");
    const bool fallback = a.is_object() && a.value("fallback", false) == true;
    s += std::string("<tr class=\"svgm-action") + (fallback ? " svgm-warn-row" : "") + "\" data-action=\"" + std::to_string(k + 1) +
         "\"><td><span class=\"svgm-swatch\" style=\"background:" + colour_of(k) + "\">" + std::to_string(k + 1) +
         "</span></td><td>" + html_escape(str(a, "verb")) + (motion_kind.empty() ? "" : "<br><small>" + html_escape(motion_kind) + "</small>") +
         "</td><td>" + parts + "</td><td>" + amplitude_text(a) + "</td><td>" + html_escape(str(a, "direction")) + "</td><td>" +
         (a.contains("cycles") && a["cycles"].is_number() ? html_number(a["cycles"].get<double>(), 3) : "-") + "</td><td>" +
         (fallback ? "<b>fallback</b>: no motion word understood, so the whole figure sways gently" : html_escape(str(a, "why"))) +
         "</td></tr>";
  }
  if (plan.empty()) s += "<tr><td colspan=\"7\">No action planned.</td></tr>";
  s += "</table></div>";
  if (!readings.empty()) s += "<p>Words read through the lexicon (WordNet):</p>" + list(readings, "svgm-readings");
  // The plan's warnings, less the two this section has said above (the fallback, the words).
  std::vector<std::string> other;
  for (const auto& w : warnings)
    if (w.rfind("no motion understood in the prompt", 0) != 0 && w.rfind("words not understood: ", 0) != 0) other.push_back(w);
  if (!other.empty()) s += "<p class=\"svgm-warn\">Warnings:</p>" + list(other, "svgm-motion-warnings");
  if (!notes.empty()) s += "<details><summary>Notes (" + std::to_string(notes.size()) + ")</summary>" + list(notes, "svgm-motion-notes") + "</details>";
  return s + "</section>\n";
}

}  // namespace svgm
