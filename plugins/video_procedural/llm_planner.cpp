// llm_planner.h: the request, the drawing with its numbered parts, and the answer's checks.
#include "llm_planner.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/chat_client.h"
#include "common/stage_files.h"
#include "image/numbered_parts.h"
#include "motion/motion_verbs.h"
#include "net/secret_scrub.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/render_size.h"
#include "svgmotion/utf8_text.h"
#include "procedural/motion_plan.h"

namespace svgm::plugin {

namespace {

using json = nlohmann::json;
using chat::Failure;
using chat::one_line;

constexpr int kRenderWidth = 512;    // px of the image sent, as the llm grouper's
constexpr int kCubicSamples = 8;     // points per cubic segment of a traced outline
constexpr size_t kMaxPlanChars = 2000;  // a longer answer is no plan line

std::string instructions() {
  std::ostringstream t;
  t << "You plan the motion of a flat 2D drawing for a short looping animation. Its parts are "
       "listed by number and name, and the image shows the drawing with each part outlined in a "
       "colour of its own and its number on it. Answer with the plan only, on one line, no other "
       "text, in this syntax:\n"
       "  verb:part[+part...] [modifier ...], verb:part ...\n"
       "verb: one of these (what each moves by default in brackets): ";
  bool first = true;
  for (const Verb& v : motion_verbs()) {
    t << (first ? "" : ", ") << v.name;
    if (!v.actions.empty())
      t << " (" << primitive_name(v.actions[0].primitive) << " " << target_name(v.actions[0].target) << ")";
    first = false;
  }
  t << ".\npart: a part's name exactly as listed (not its number), several joined by '+'; '*' matches "
       "any characters (wing_*); 'whole' moves the whole figure, 'repeated' the repeated small "
       "elements; leave out ':part' to let the verb move what it moves by default.\n"
       "modifier (optional, after a space): slow, fast, gently, wildly, once, repeatedly, left, "
       "right, up, down, both (left and right are the figure's own sides).\n"
       "Several items are separated by commas. Move only what the motion asked for needs; the "
       "background stays still unless asked. Example: flap:wing_left+wing_right fast, bob:whole gently";
  return t.str();
}

std::string user_text(const Rig& rig, const Scene& scene, const std::string& prompt) {
  std::ostringstream t;
  t << "Parts of the drawing (canvas " << std::lround(scene.width) << " x " << std::lround(scene.height)
    << "; box: left, top, right, bottom in canvas units, y down):\n";
  for (size_t i = 0; i < rig.parts.size(); ++i) {
    const RigPart& p = rig.parts[i];
    t << i + 1 << ". " << p.name << " (" << role_name(p.role);
    if (p.side) t << (p.side > 0 ? ", the figure's right" : ", the figure's left");
    if (p.round) t << ", round: a wheel";
    t << "), box " << std::lround(p.box.x0) << ", " << std::lround(p.box.y0) << ", " << std::lround(p.box.x1) << ", "
      << std::lround(p.box.y1) << "\n";
  }
  if (!rig.repeated.empty()) t << "Repeated small elements: " << rig.repeated.size() << "\n";
  t << "\nMotion asked for: " << (prompt.empty() ? std::string("(not described; choose what the drawing suggests)") : prompt);
  return t.str();
}

// The recoloured drawing at rest with every part outlined and numbered, as PNG bytes.
std::string numbered_drawing(const Scene& scene, const Rig& rig, const std::string& device) {
  RgbaImage image = render_image(scene, kRenderWidth, device);
  const Affine view = render_size(scene, kRenderWidth).view;
  std::vector<NumberedPart> marks(rig.parts.size());
  for (size_t i = 0; i < marks.size(); ++i) {
    marks[i].number = static_cast<int>(i) + 1;
    marks[i].box_min = view.apply({rig.parts[i].box.x0, rig.parts[i].box.y0});
    marks[i].box_max = view.apply({rig.parts[i].box.x1, rig.parts[i].box.y1});
  }
  for (size_t p = 0; p < scene.paths.size() && p < rig.part_of_path.size(); ++p) {
    const int part = rig.part_of_path[p];
    if (part < 0 || part >= static_cast<int>(marks.size())) continue;
    for (const Subpath& sp : scene.paths[p].subpaths) {
      std::vector<Vec2> line;
      for (size_t s = 0; s < sp.segment_count(); ++s) {
        const Vec2 *c = &sp.points[3 * s];
        for (int k = s == 0 ? 0 : 1; k <= kCubicSamples; ++k) {
          const double u = static_cast<double>(k) / kCubicSamples, v = 1 - u;
          line.push_back(view.apply(v * v * v * c[0] + 3 * v * v * u * c[1] + 3 * v * u * u * c[2] + u * u * u * c[3]));
        }
      }
      if (sp.closed && !line.empty()) line.push_back(line.front());
      marks[static_cast<size_t>(part)].outlines.push_back(std::move(line));
    }
  }
  draw_numbered_parts(image, marks);
  return encode_png(image);
}

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

std::vector<ExplicitStep> check_llm_plan(const std::string& answer, const Rig& rig, std::string& plan_line) {
  std::string s = trimmed(chat::strip_fences(answer));
  // `flap:wing*` or "flap:wing*": a model quoting its line.
  while (s.size() >= 2 && s.front() == s.back() && (s.front() == '`' || s.front() == '"' || s.front() == '\''))
    s = trimmed(s.substr(1, s.size() - 2));
  if (s.empty()) throw Failure("the model's plan is empty");
  if (s.size() > kMaxPlanChars) throw Failure("malformed plan: " + std::to_string(s.size()) + " characters, not one plan line");
  if (s.find_first_of("\r\n") != std::string::npos)
    throw Failure("malformed plan: more than one line ('" + one_line(s, 120) + "')");
  std::vector<ExplicitStep> steps;
  try {
    steps = parse_explicit_plan(s);
  } catch (const Error& e) {
    throw Failure("invalid plan from the model: " + one_line(e.what()));
  }
  // The parts named: exactly as an explicit plan's (plan_from_steps throws for a pattern that
  // matches no part); its message names the option, which the model did not write.
  try {
    (void)plan_from_steps(steps, rig, 0);
  } catch (const Error& e) {
    std::string why = e.what();
    const std::string option = "stages.video.options.motion: ";
    if (why.rfind(option, 0) == 0) why = why.substr(option.size());
    throw Failure("invalid plan from the model: motion plan '" + one_line(s, 120) + "': " + one_line(why));
  }
  plan_line = s;
  return steps;
}

LlmPlan ask_llm_planner(const json& options, const Scene& scene, const Rig& rig, const std::string& prompt, uint32_t seed,
                        const std::string& device, const svgm_host* host) {
  const chat::Settings s = chat::read_settings(options, "video");
  if (rig.parts.empty()) throw Failure("the drawing has no parts to plan for");
  std::string png;
  try {
    png = numbered_drawing(scene, rig, device);
  } catch (const std::exception& e) {
    throw Failure("cannot render the drawing for the model: " + one_line(e.what(), 200));
  }
  // Deterministic: temperature 0 and the run's seed (OpenAI and Ollama take one; others ignore it).
  const json body = {
      {"model", s.model},
      {"messages", json::array({{{"role", "system"}, {"content", instructions()}},
                                {{"role", "user"},
                                 {"content", json::array({{{"type", "text"}, {"text", user_text(rig, scene, prompt)}},
                                                          {{"type", "image_url"},
                                                           {"image_url", {{"url", "data:image/png;base64," + chat::base64(png)}}}}})}}})},
      {"temperature", 0},
      {"seed", seed}};
  LlmPlan out;
  out.model = s.model;
  // The reply's body is scrubbed of the key, but its text parts are joined and unescaped after:
  // scrubbed again, so a key the server splits or escapes reaches no log, motion.json or report.
  out.answer = scrub_secret(chat::answer_text(chat::post(s, json_text(body), host, "video procedural")), s.api_key);
  out.steps = check_llm_plan(out.answer, rig, out.plan);
  return out;
}

PlannerOutcome run_llm_planner(const json& options, const Scene& scene, const Rig& rig, const std::string& prompt, uint32_t seed,
                               const std::string& device, const svgm_host* host) {
  PlannerOutcome out;
  try {
    LlmPlan asked = ask_llm_planner(options, scene, rig, prompt, seed, device, host);
    out.from_llm = true;
    out.steps = std::move(asked.steps);
    out.record = {{"planner", "llm"}, {"source", "llm"}, {"model", asked.model}, {"plan", asked.plan}, {"answer", asked.answer}};
    if (host && host->log) host->log(host, 1, ("video procedural: the llm planner's plan: " + asked.plan).c_str());
  } catch (const Failure& f) {
    const std::string why = one_line(f.what());
    out.record = {{"planner", "llm"}, {"source", "offline"}, {"fallback", why}};
    if (host && host->log) host->log(host, 2, ("video procedural: planner llm: " + why + "; using the offline planner").c_str());
  }
  return out;
}

}  // namespace svgm::plugin
