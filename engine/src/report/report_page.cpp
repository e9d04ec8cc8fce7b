// report.html (see report_page.h). Each section is one function reading its own files; a
// missing file is said in its section, so a run stopped early (flagged candidates, a rejected
// fit) still gets a page that shows what there is.
#include "report/report_page.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "export/smil_clock.h"
#include "net/base64.h"
#include "opencl/runtime.h"
#include "pipeline/pipeline.h"
#include "raster/render_image.h"
#include "report/html_text.h"
#include "report/inline_svg.h"
#include "report/lottie_frames.h"
#include "report/report_downloads.h"
#include "report/user_colours.h"
#include "report/report_motion.h"
#include "report/report_charts.h"
#include "report/rerun_command.h"
#include "report/sha256.h"
#include "report/video_frames.h"
#include "pipeline/candidate_choice.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "svgmotion/render_size.h"
#include "svgmotion/svg_reader.h"
#include "generators/candidates.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  json j = json::parse(in, nullptr, false);
  return j.is_discarded() ? json(nullptr) : j;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string png_uri(const RgbaImage& img) { return "data:image/png;base64," + base64(encode_png(img)); }

// `shown_width` > 0 scales the picture on the page (a 128-px target frame beside a 256-px render).
std::string img_tag(const RgbaImage& img, const std::string& alt, int shown_width = 0) {
  const int w = shown_width > 0 ? shown_width : img.width;
  const int h = static_cast<int>(std::lround(static_cast<double>(img.height) * w / std::max(1, img.width)));
  return "<img src=\"" + png_uri(img) + "\" width=\"" + std::to_string(w) + "\" height=\"" + std::to_string(h) +
         "\" alt=\"" + html_escape(alt) + "\">";
}

std::string text_of(const json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

std::vector<double> numbers(const json& j) {
  std::vector<double> v;
  if (j.is_array())
    for (const json& x : j) v.push_back(x.is_number() ? x.get<double>() : NAN);
  return v;
}

std::string missing(const std::string& what) { return "<p class=\"svgm-missing\">" + html_escape(what) + "</p>"; }

std::string section(const char* id, const char* title, const std::string& body) {
  return std::string("<section id=\"") + id + "\"><h2>" + title + "</h2>" + body + "</section>\n";
}

// The renderer, made when the first picture needs it (the page of a run stopped before any
// picture can be drawn never opens the device).
class Renderer {
 public:
  explicit Renderer(std::string device) : device_(std::move(device)) {}
  RgbaImage render(const Scene& scene, int width) {
    if (!rt_) rt_ = std::make_unique<ClRuntime>(device_);
    return render_image(*rt_, scene, width, false);
  }

 private:
  std::string device_;
  std::unique_ptr<ClRuntime> rt_;
};

struct RunFiles {
  fs::path run, animation;  // animation.svg, or animation.failed.svg, or empty
  json fit, ranking, command, motion;
};

std::string summary_section(const RunFiles& f) {
  std::string s = "<h1>svgmotion run: " + html_escape(f.run.filename().string()) + "</h1><p>";
  std::string prompt = text_of(f.command, "prompt");
  if (prompt.empty()) prompt = text_of(f.motion, "prompt");
  s += "Prompt: <q id=\"svgm-prompt\">" + html_escape(prompt) + "</q><br>";
  s += "Run directory: <code>" + html_escape(f.run.string()) + "</code><br>";
  const std::string status = text_of(f.fit, "status");
  // A fit that followed its target well of a motion that is not what the prompt asked (words not
  // understood, the fallback sway) is not plainly "ok": the status says so, and why.
  const MotionCaveat why = motion_caveat(f.motion);
  const std::string& caveat = why.line;
  const std::string shown = status == "ok" && !caveat.empty()
                                ? (why.fallback ? "ok, but the motion is a fallback" : "ok, but words not understood") : status;
  if (!f.fit.is_object()) s += "No fit yet (fit.json is missing): the run stopped before the fitter.";
  else
    s += "Fit: <b class=\"svgm-status-" + html_escape(status == "ok" && !caveat.empty() ? "warn" : status) + "\">" +
         html_escape(shown) + "</b>, " +
         html_escape(std::to_string(f.fit.value("keyframes", 0))) + " keyframes, " +
         html_escape(std::to_string(f.fit.value("iterations", 0))) + " iterations, " +
         html_number(f.fit.value("seconds", 0.0), 3) + " s on " + html_escape(text_of(f.fit, "device")) + ".";
  s += "</p>";
  if (!caveat.empty())
    s += "<p class=\"svgm-caveat\" id=\"svgm-caveat\">The motion: " + html_escape(caveat) + ".</p>";
  if (f.fit.is_object() && f.fit.contains("gate") && f.fit["gate"].is_object() && f.fit["gate"].contains("reasons") &&
      f.fit["gate"]["reasons"].is_array() && !f.fit["gate"]["reasons"].empty()) {
    s += "<p>The result gate's reasons:</p><ul>";
    for (const json& r : f.fit["gate"]["reasons"])
      if (r.is_string()) s += "<li>" + html_escape(r.get<std::string>()) + "</li>";
    s += "</ul>";
  }
  return "<header id=\"svgm-summary\">" + s + "</header>\n";
}

// The Lottie file beside the SVG: its frames as librlottie draws them, shown in step with the
// SVG's clock by the page's script (report/lottie_frames.h says why frames, not a player).
std::string lottie_figure(const RunFiles& f, const ReportOptions& o, int height, std::vector<std::string>& notes) {
  const fs::path json = f.animation.parent_path() / (f.animation.stem().string() + ".json");
  std::error_code ec;
  if (!fs::is_regular_file(json, ec))
    return "<figure id=\"svgm-lottie\">" + missing("No " + json.filename().string() + " (Lottie) in the run directory.") +
           "</figure>";
  std::string why;
  const auto frames = lottie_frames(json, o.player_width, o.max_lottie_frames, why);
  if (!frames) {
    notes.push_back("Lottie not drawn: " + why);
    return "<figure id=\"svgm-lottie\">" + missing("The Lottie file is not drawn here: " + why + ".") + "</figure>";
  }
  std::string s = "<figure id=\"svgm-lottie\" style=\"width:" + std::to_string(o.player_width) + "px\" data-duration=\"" +
                  html_number(frames->duration_s, 9) + "\"><div class=\"svgm-lottie-box\" style=\"width:" + std::to_string(o.player_width) + "px;height:" +
                  std::to_string(height) + "px\">";
  for (size_t i = 0; i < frames->frames.size(); ++i)
    s += "<img src=\"" + png_uri(frames->frames[i]) + "\" alt=\"Lottie frame " + std::to_string(i) + "\"" +
         (i ? " hidden" : "") + ">";
  s += "</div><figcaption>" + html_escape(json.filename().string()) + " as " + html_escape(frames->player) +
       " (a Lottie player) draws it: " + std::to_string(frames->frames.size()) +
       " frames drawn when this page was written, shown in step with the SVG. The page runs no third-party "
       "player itself.</figcaption></figure>";
  return s;
}

std::string player_section(const RunFiles& f, const ReportOptions& o, std::vector<std::string>& notes) {
  if (f.animation.empty()) return section("svgm-player", "The animation", missing("No animation.svg in the run directory yet."));
  const std::string text = read_bytes(f.animation);
  double duration = 0;
  InlinedSvg svg;
  int height = 0;
  try {
    duration = smil_clock(text, f.animation.string()).duration_s;
    svg = inline_svg(f.animation);
    height = render_size(read_svg_file(f.animation), o.player_width).height;
  } catch (const Error& e) {
    notes.push_back(std::string("animation not shown: ") + e.what());
    return section("svgm-player", "The animation", missing(std::string("The animation cannot be shown: ") + e.what()));
  }
  std::string s = "<p>" + html_escape(f.animation.filename().string()) +
                  " as your browser plays it (SMIL). Drag the scrubber to see any moment.</p>";
  if (!svg.dropped.empty()) {
    notes.push_back("dropped from the inlined animation: " + svg.dropped);
    s += "<p class=\"svgm-missing\" id=\"svgm-dropped\">Left out of the animation on this page, which keeps only what "
         "a drawing and its animation need (nothing that could run or load a file): " + html_escape(svg.dropped) + ".</p>";
  }
  s += "<div class=\"svgm-row\"><figure style=\"width:" + std::to_string(o.player_width) + "px\"><div id=\"svgm-stage\" style=\"width:" + std::to_string(o.player_width) +
       "px;height:" + std::to_string(height) + "px\">" + svg.markup + "</div><figcaption>" +
       html_escape(f.animation.filename().string()) + " in your browser (SMIL)</figcaption></figure>" +
       lottie_figure(f, o, height, notes) + "</div>";
  s += "<div class=\"svgm-controls\"><button id=\"svgm-play\" type=\"button\">Pause</button> "
       "<input id=\"svgm-scrub\" type=\"range\" min=\"0\" max=\"" + html_number(duration, 9) +
       "\" step=\"any\" value=\"0\" aria-label=\"time\"> <span id=\"svgm-time\">0.00</span> / " +
       html_number(duration, 4) + " s</div>";
  return section("svgm-player", "The animation", s);
}

// The drawing at rest for the motion section's outlines, as a data: URI ("" when it cannot be
// drawn, or when there is no motion.json to outline).
std::string motion_drawing(const RunFiles& f, Renderer& r, const ReportOptions& o, std::vector<std::string>& notes) {
  if (!f.motion.is_object()) return "";
  try {
    return png_uri(r.render(read_svg_file(f.run / "input.svg"), o.thumb_width));
  } catch (const Error& e) {
    notes.push_back(std::string("motion outlines not drawn: ") + e.what());
    return "";
  }
}

std::string input_section(const RunFiles& f, Renderer& r, const ReportOptions& o, std::vector<std::string>& notes) {
  std::string s = "<div class=\"svgm-row\">";
  try {
    s += "<figure>" + img_tag(r.render(read_svg_file(f.run / "input.svg"), o.thumb_width), "input drawing") +
         "<figcaption>input.svg</figcaption></figure>";
  } catch (const Error& e) {
    notes.push_back(std::string("input not drawn: ") + e.what());
    s += missing(std::string("input.svg cannot be drawn: ") + e.what());
  }
  std::error_code ec;
  if (fs::is_regular_file(f.run / "recolored.png", ec)) {
    try {
      RgbaImage img = read_png(f.run / "recolored.png");
      s += "<figure><img src=\"data:image/png;base64," + base64(read_bytes(f.run / "recolored.png")) +
           "\" width=\"" + std::to_string(std::min(img.width, o.thumb_width)) +
           "\" alt=\"recoloured drawing\"><figcaption>recolored.png: what the video model was shown</figcaption></figure>";
    } catch (const Error& e) {
      s += missing(std::string("recolored.png cannot be read: ") + e.what());
    }
  }
  return section("svgm-input", "The input", s + "</div>");
}

// One candidate's scores as the ranker wrote them: the score, the defects, every signal with
// its reason, and the judge's verdicts when an llm ranker judged it.
std::string candidate_scores(const json& c, const json& judge, const std::string& name) {
  std::string s;
  if (!c.is_object()) return "<p>Not in ranking.json.</p>";
  if (c.contains("score")) s += "<p>Score " + (c["score"].is_number() ? html_number(c["score"].get<double>()) : "-") +
                                " <small>(lower is better)</small></p>";
  if (c.contains("error") && c["error"].is_string()) s += "<p class=\"svgm-defect\">" + html_escape(c["error"].get<std::string>()) + "</p>";
  if (c.contains("defects") && c["defects"].is_array() && !c["defects"].empty()) {
    s += "<ul class=\"svgm-defects\">";
    for (const json& d : c["defects"])
      if (d.is_string()) s += "<li>" + html_escape(d.get<std::string>()) + "</li>";
    s += "</ul>";
  }
  if (c.contains("signals") && c["signals"].is_object()) {
    // Folded: five rows of reasons made each card twice as tall as its frames.
    s += "<details><summary>the ranker's signals (" + std::to_string(c["signals"].size()) +
         ")</summary><table class=\"svgm-signals\"><tr><th>signal</th><th>value</th><th>reason</th></tr>";
    for (const auto& [k, v] : c["signals"].items())
      s += "<tr><td>" + html_escape(k) + "</td><td>" +
           (v.is_object() && v.contains("value") && v["value"].is_number() ? html_number(v["value"].get<double>(), 3) : "-") +
           "</td><td>" + html_escape(text_of(v, "reason")) + "</td></tr>";
    s += "</table></details>";
  }
  if (judge.is_object() && judge.contains("scores") && judge["scores"].is_array())
    for (const json& j : judge["scores"])
      if (text_of(j, "candidate") == name) {
        s += "<p class=\"svgm-judge\">Judge: ";
        for (const auto& [k, v] : j.items())
          if (k != "candidate" && k != "answer" && k != "reason" && (v.is_string() || v.is_boolean() || v.is_number()))
            s += html_escape(k) + " " + html_escape(v.is_string() ? v.get<std::string>() : json_text(v)) + "; ";
        s += html_escape(text_of(j, "reason")) + "</p>";
      }
  return s;
}

// Four frames of a candidate (first, a quarter, half, three quarters through) in the user's
// colours (report/user_colours.h), or as made when there is no palette to map back.
std::string candidate_frames(const fs::path& file, const ColourMap* colours, const ReportOptions& o) {
  try {
    const int n = video_frame_count(file);
    std::vector<int> at;
    for (int q = 0; q < 4; ++q) at.push_back(n * q / 4);
    std::vector<RgbaImage> frames = video_frames(file, at, o.thumb_width / 2);
    std::string s = "<div class=\"svgm-frames\">";
    for (size_t i = 0; i < frames.size(); ++i) {
      if (colours) to_user_colours(frames[i], *colours);
      s += img_tag(frames[i], "frame " + std::to_string(at[i]) + (colours ? " in your colours" : ""), o.thumb_width / 2);
    }
    return s + "</div><p><small>Frames " + std::to_string(at[0]) + ", " + std::to_string(at[1]) + ", " +
           std::to_string(at[2]) + ", " + std::to_string(at[3]) + " of " + std::to_string(n) +
           (colours ? ", in your drawing's colours (each recoloured part mapped back to its own colour)" : "") +
           ".</small></p>";
  } catch (const Error& e) {
    return missing(std::string("Frames not read: ") + e.what());
  }
}

std::string candidates_section(const RunFiles& f, const ReportOptions& o, std::vector<std::string>& notes) {
  std::vector<std::string> names;
  for (const fs::path& p : list_candidates(f.run / "candidates")) names.push_back(p.filename().string());
  const json& rc = f.ranking.is_object() && f.ranking.contains("candidates") ? f.ranking["candidates"] : json();
  if (rc.is_array())
    for (const json& c : rc)
      if (const std::string n = text_of(c, "name"); !n.empty() && std::find(names.begin(), names.end(), n) == names.end())
        names.push_back(n);
  if (names.empty()) return section("svgm-candidates", "Candidate videos", missing("No candidate videos in the run directory yet."));
  const std::string chosen = text_of(f.ranking, "chosen"), ranker_pick = text_of(f.ranking, "ranker_chosen");
  std::string s;
  if (f.ranking.is_object()) {
    s += "<p>The ranker's choice: " + html_escape(ranker_pick.empty() ? chosen : ranker_pick) + ", " +
         html_escape(text_of(f.ranking, "reason")) + ".";
    if (!ranker_pick.empty())
      s += " Fitted instead, by hand (" + html_escape(text_of(f.ranking, "chosen_by")) + "): " + html_escape(chosen) + ".";
    s += "</p>";
  } else {
    s += missing("No ranking.json: the ranker has not run.");
  }
  std::string no_colours;
  const std::optional<ColourMap> colours = user_colour_map(f.run, no_colours);
  if (!colours) notes.push_back("candidates shown as made: " + no_colours);
  s += "<div class=\"svgm-grid\">";
  size_t budget = o.max_video_bytes;
  for (const std::string& name : names) {
    const fs::path file = f.run / "candidates" / name;
    json entry;
    if (rc.is_array())
      for (const json& c : rc)
        if (text_of(c, "name") == name) entry = c;
    // Before any fit (every candidate flagged) the chosen one is target.mp4, not yet fitted, and
    // its command too is worth showing: a hand choice is fitted even when flagged.
    const bool is_chosen = name == chosen, fitted = is_chosen && f.fit.is_object();
    s += std::string("<div class=\"svgm-candidate") + (is_chosen ? " svgm-chosen" : "") + "\" data-name=\"" +
         html_escape(name) + "\"><h3>" + html_escape(name) +
         (is_chosen ? std::string(" <span class=\"svgm-badge\">") + (fitted ? "fitted" : "chosen") + "</span>" : "") +
         (!ranker_pick.empty() && name == ranker_pick ? " <span class=\"svgm-badge\">ranker's pick</span>" : "") + "</h3>";
    std::error_code ec;
    const std::string ext = file.extension().string();
    if (fs::is_regular_file(file, ec) && (ext == ".mp4" || ext == ".webm")) {
      const auto size = static_cast<size_t>(fs::file_size(file, ec));
      if (size <= budget) {
        budget -= size;
        std::string poster;
        try {
          poster = " poster=\"" + png_uri(video_frames(file, {0}, o.thumb_width).front()) + "\"";
        } catch (const Error&) {
        }
        s += candidate_frames(file, colours ? &*colours : nullptr, o);
        s += std::string("<details") + (colours ? "" : " open") + "><summary>the video as made" +
             (colours ? " (in the recoloured palette the video model was shown)" : "") +
             "</summary><video controls loop muted playsinline preload=\"auto\" width=\"" + std::to_string(o.thumb_width) + "\"" +
             poster + " src=\"data:video/" + ext.substr(1) + ";base64," + base64(read_bytes(file)) + "\"></video></details>";
      } else {
        notes.push_back("candidate " + name + " not embedded: the page's video budget (" +
                        std::to_string(o.max_video_bytes >> 20) + " MB) is spent");
        s += missing("Not embedded (" + std::to_string(size >> 10) + " kB would pass the page's " +
                     std::to_string(o.max_video_bytes >> 20) + " MB video budget): open candidates/" + name + ".");
      }
    } else if (fs::exists(file, ec)) {
      s += missing("Not embedded (" + std::string(fs::is_directory(file, ec) ? "a folder of frames" : "not an mp4 or webm") +
                   "): open candidates/" + name + ".");
    } else {
      s += missing("candidates/" + name + " is no longer in the run directory.");
    }
    s += candidate_scores(entry, f.ranking.is_object() && f.ranking.contains("judge") ? f.ranking["judge"] : json(), name);
    if (fitted) {
      s += "<p>This is the candidate the fit used.</p>";
    } else if (const auto cmd = choose_command(f.run, name)) {
      s += "<button type=\"button\" class=\"svgm-use\">Use this one</button><pre class=\"svgm-cmd\" hidden>" +
           html_escape(*cmd) + "</pre>";
    } else {
      s += "<p class=\"svgm-cmd-note\">This run did not record its command: add <code>" +
           html_escape(std::string(kChooseKey) + "=" + name) + "</code> to the command that made it.</p>";
    }
    s += "</div>";
  }
  s += "</div><p><small>\"Use this one\" shows the command that fits that candidate instead: the same settings "
       "with stages.ranker.choose, so the stages before the ranker are up to date and layers, tracker and fitter "
       "run again on it.</small></p>";
  return section("svgm-candidates", "Candidate videos", s);
}

std::string compare_section(const RunFiles& f, Renderer& r, const ReportOptions& o, std::vector<std::string>& notes) {
  std::string s;
  std::error_code ec;
  const fs::path preview = f.run / "preview.mp4";
  if (fs::is_regular_file(preview, ec) && fs::file_size(preview, ec) <= o.max_video_bytes)
    s += "<p>preview.mp4, the target | the fit at each keyframe (in the target's colours):</p>"
         "<video id=\"svgm-preview\" controls loop muted playsinline src=\"data:video/mp4;base64," +
         base64(read_bytes(preview)) + "\"></video>";
  if (!f.fit.is_object() || f.animation.empty())
    return section("svgm-compare", "The target beside the fit", s + missing("No fit yet (fit.json or the animation is missing)."));
  const std::vector<double> key_times = numbers(f.fit.value("key_times", json()));
  const double duration = f.fit.value("duration_s", 0.0);
  std::vector<int> frames;
  if (f.fit.contains("keyframe_frames") && f.fit["keyframe_frames"].is_array())
    for (const json& k : f.fit["keyframe_frames"]) frames.push_back(k.is_number_integer() ? k.get<int>() : 0);
  std::vector<RgbaImage> target;
  try {
    if (frames.size() != key_times.size()) {  // a fit.json written before keyframe_frames
      const int n = video_frame_count(f.run / "target.mp4");
      frames.clear();
      for (double t : key_times) frames.push_back(static_cast<int>(std::lround(t * (n - 1))));
    }
    target = video_frames(f.run / "target.mp4", frames, o.thumb_width);
  } catch (const Error& e) {
    notes.push_back(std::string("target frames not shown: ") + e.what());
    s += missing(std::string("The target's frames cannot be read: ") + e.what());
  }
  const json gate = f.fit.value("gate", json());
  const std::vector<double> loss = numbers(f.fit.value("keyframe_image_loss", json()));
  const std::vector<double> psnr = numbers(gate.is_object() ? gate.value("keyframe_psnr_db", json()) : json());
  const std::vector<double> iou = numbers(gate.is_object() ? gate.value("keyframe_iou", json()) : json());
  s += "<details id=\"svgm-keyframes\"><summary>Each keyframe (" + std::to_string(key_times.size()) +
       "): the target's frame (target.mp4) and the animation at the same time, drawn by svgmotion's "
       "renderer in your colours</summary><table class=\"svgm-keys\"><tr><th>keyframe</th><th>target</th><th>fit</th>"
       "<th>image loss</th><th>PSNR</th><th>IoU</th></tr>";
  for (size_t k = 0; k < key_times.size(); ++k) {
    const double t = key_times[k] * duration;
    s += "<tr><td>" + std::to_string(k) + "<br><small>" + html_number(t, 3) + " s, frame " +
         (k < frames.size() ? std::to_string(frames[k]) : std::string("?")) + "</small></td><td>";
    if (k < target.size()) s += img_tag(target[k], "target keyframe " + std::to_string(k), o.thumb_width);
    s += "</td><td>";
    try {
      SvgReadLimits at;
      at.animation_time = t;
      s += img_tag(r.render(read_svg_file(f.animation, at), o.thumb_width), "fit at keyframe " + std::to_string(k),
                   o.thumb_width);
    } catch (const Error& e) {
      if (k == 0) notes.push_back(std::string("fit not drawn: ") + e.what());
      s += html_escape(e.what());
    }
    auto cell = [](const std::vector<double>& v, size_t i, int digits) {
      return "<td>" + (i < v.size() ? html_number(v[i], digits) : std::string("-")) + "</td>";
    };
    s += "</td>" + cell(loss, k, 4) + cell(psnr, k, 3) + cell(iou, k, 3) + "</tr>";
  }
  s += "</table></details>";
  return section("svgm-compare", "The target beside the fit", s);
}

std::string loss_section(const RunFiles& f) {
  if (!f.fit.is_object()) return section("svgm-losses", "The fit's loss", missing("No fit.json yet."));
  std::string s;
  const json h = f.fit.value("loss_history", json());
  const std::string curve =
      h.is_object() ? line_chart_svg(numbers(h.value("iteration", json())), numbers(h.value("total", json())),
                                     {"Loss over iterations", "iteration", "total loss"}, true)
                    : std::string();
  s += curve.empty() ? missing("No loss history in fit.json (written by svgmotion before it was recorded).")
                     : "<figure class=\"svgm-chart-box\">" + curve + "<figcaption>Sampled every " +
                           std::to_string(h.value("every", 0)) +
                           " iterations; it rises when a keyframe is activated (each adds its own loss).</figcaption></figure>";
  const std::string bars = bar_chart_svg(numbers(f.fit.value("keyframe_image_loss", json())),
                                         {"Image loss per keyframe", "keyframe", "image loss"});
  s += bars.empty() ? missing("No per-keyframe losses in fit.json.") : "<figure class=\"svgm-chart-box\">" + bars + "</figure>";
  if (f.fit.contains("rollbacks") && f.fit["rollbacks"].is_array() && !f.fit["rollbacks"].empty()) {
    s += "<p>Rollbacks of a diverging loss:</p><ul>";
    for (const json& r : f.fit["rollbacks"])
      if (r.is_string()) s += "<li>" + html_escape(r.get<std::string>()) + "</li>";
    s += "</ul>";
  }
  return section("svgm-losses", "The fit's loss", s);
}

std::string timings_section(const RunFiles& f) {
  std::string s = "<table class=\"svgm-timings\"><tr><th>stage</th><th>plugin</th><th>seconds</th></tr>";
  double total = 0;
  int rows = 0;
  for (const StageFiles& sf : stage_files()) {
    const json m = read_json(f.run / ".svgmotion" / (sf.stage + ".json"));
    double sec = m.is_object() && m.contains("seconds") && m["seconds"].is_number() ? m["seconds"].get<double>() : NAN;
    std::string plugin = text_of(m, "plugin");
    if (!std::isfinite(sec) && sf.stage == "fitter" && f.fit.is_object())  // a rejected fit leaves no manifest
      sec = f.fit.value("seconds", NAN);
    if (std::isfinite(sec)) total += sec;
    rows += std::isfinite(sec);
    s += "<tr><td>" + html_escape(sf.stage) + "</td><td>" + html_escape(plugin) + "</td><td>" +
         (std::isfinite(sec) ? html_number(sec, 3) : std::string("not run")) + "</td></tr>";
  }
  s += "<tr><th>total</th><td></td><th>" + html_number(total, 3) + "</th></tr></table>";
  s += "<p><small>Seconds of each stage when it last ran (a stage that was up to date kept its time); the fitter's "
       "own time is in fit.json.</small></p>";
  if (rows == 0) s += missing("No stage has recorded a time yet.");
  return section("svgm-timings", "Timings per stage", s);
}

// #svgm-stage clips what it holds (overflow, contain: paint): the user's drawing, however it is
// transformed, never paints over the page's own text (a made-up command beside the real ones).
constexpr const char* kStyle = R"(<style>
body{font:14px/1.4 system-ui,sans-serif;margin:16px 24px;color:#222;background:#fafafa}
section{background:#fff;border:1px solid #ddd;border-radius:6px;padding:8px 16px;margin:12px 0}
h1{font-size:20px}h2{font-size:17px;margin:6px 0}h3{font-size:15px;margin:4px 0}
figure{display:inline-block;margin:4px 12px 4px 0;vertical-align:top}figcaption{font-size:12px;color:#555}
img,video{border:1px solid #ccc;background:#fff;max-width:100%}
#svgm-stage{border:1px solid #ccc;background:#fff;overflow:hidden;contain:paint}#svgm-stage>svg{display:block}
.svgm-controls{margin:8px 0}#svgm-scrub{width:300px;vertical-align:middle}
.svgm-grid{display:flex;flex-wrap:wrap;gap:12px}
.svgm-candidate{border:1px solid #ddd;border-radius:6px;padding:8px;width:270px}
.svgm-chosen{border:2px solid #1f6fb4}.svgm-badge{background:#1f6fb4;color:#fff;border-radius:4px;padding:0 5px;font-size:12px}
.svgm-defect,.svgm-defects{color:#a33}.svgm-missing{color:#777;font-style:italic}
table{border-collapse:collapse}td,th{border-bottom:1px solid #eee;padding:2px 6px;text-align:left;vertical-align:top;font-size:13px}
.svgm-signals td{font-size:12px}pre.svgm-cmd{white-space:pre-wrap;word-break:break-all;background:#f3f3f3;padding:6px;font-size:12px}
.svgm-status-ok{color:#2a7a2a}.svgm-status-rejected{color:#a33}.svgm-status-warn{color:#8a5a00;background:#fff3d6;padding:0 4px}
.svgm-caveat{background:#fff3d6;border-left:4px solid #e0a000;padding:4px 8px;color:#5a3d00}
.svgm-swatch{display:inline-block;min-width:18px;color:#fff;text-align:center;border-radius:3px;font-weight:600}
tr.svgm-warn-row td{background:#fff3d6}
.svgm-row{display:flex;flex-wrap:wrap;gap:12px;align-items:flex-start}.svgm-warn{color:#a33;font-weight:600}
#svgm-lottie .svgm-lottie-box{border:1px solid #ccc;background:#fff;overflow:hidden}#svgm-lottie img{border:0;display:block;width:100%}#svgm-lottie img[hidden]{display:none}
.svgm-frames img{margin:0 2px 2px 0}details>summary{cursor:pointer;margin:4px 0}
svg.svgm-motion-parts{border:1px solid #ccc;background:#fff;max-width:100%;height:auto;flex:none}table.svgm-plan{flex:1 1 520px}
</style>)";

// The player: play/pause and a scrubber over the inline SVG's SMIL clock. The scrubber follows
// the clock while playing; moving it pauses and seeks. "#t=1.5" in the address opens the page
// paused at 1.5 s.
constexpr const char* kScript = R"(<script>
(function () {
  var svg = document.querySelector('#svgm-stage > svg');
  var play = document.getElementById('svgm-play'), scrub = document.getElementById('svgm-scrub');
  var label = document.getElementById('svgm-time');
  if (svg && play && scrub) {
    var dur = Number(scrub.max) || 0;
    var lottie = document.getElementById('svgm-lottie');
    var frames = lottie ? lottie.querySelectorAll('img') : [];
    var ldur = lottie ? Number(lottie.dataset.duration) || 0 : 0;
    var shown = 0;
    var show = function (t) {
      label.textContent = t.toFixed(2);
      if (frames.length && ldur > 0) {
        var i = Math.min(frames.length - 1, Math.floor((t % ldur) / ldur * frames.length));
        if (i !== shown) { frames[shown].hidden = true; frames[i].hidden = false; shown = i; }
      }
    };
    var seek = function (t) {
      svg.pauseAnimations();
      svg.setCurrentTime(t);
      scrub.value = String(t);
      play.textContent = 'Play';
      show(t);
    };
    play.addEventListener('click', function () {
      if (svg.animationsPaused()) { svg.unpauseAnimations(); play.textContent = 'Pause'; }
      else { svg.pauseAnimations(); play.textContent = 'Play'; }
    });
    scrub.addEventListener('input', function () { seek(Number(scrub.value)); });
    var tick = function () {
      if (!svg.animationsPaused() && dur > 0) {
        var t = svg.getCurrentTime() % dur;
        scrub.value = String(t);
        show(t);
      }
      window.requestAnimationFrame(tick);
    };
    window.requestAnimationFrame(tick);
    var m = /(?:^#|&)t=([0-9.]+)/.exec(window.location.hash);
    if (m) seek(Number(m[1]));
    window.svgmSeek = seek;
  }
  document.querySelectorAll('.svgm-use').forEach(function (b) {
    b.addEventListener('click', function () {
      var pre = b.nextElementSibling;
      pre.hidden = !pre.hidden;
      if (!pre.hidden) window.getSelection().selectAllChildren(pre);
    });
  });
})();
</script>)";

// The page's policy, first in <head> so it governs everything after it: only the page's own
// script runs (by its hash, so no inline handler, javascript: URL or injected <script> does),
// pictures and videos come only from the data: URIs the page embeds, and nothing is fetched,
// framed, submitted or used as a base. Styles stay 'unsafe-inline' (the page and the drawing
// style inline): CSS cannot run script, and every load it could make is refused by the rest.
std::string content_security_policy() {
  std::string script(kScript);
  const size_t open = script.find('>') + 1, close = script.rfind("</script>");
  const std::string hash = base64(sha256(std::string_view(script).substr(open, close - open)));
  return "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'sha256-" + hash +
         "'; style-src 'unsafe-inline'; img-src data:; media-src data:; base-uri 'none'; form-action 'none'\">";
}

}  // namespace

ReportResult write_report(const fs::path& run_in, const ReportOptions& o) {
  const fs::path run = fs::absolute(run_in).lexically_normal();
  std::error_code ec;
  if (!fs::is_directory(run, ec)) throw Error(run_in.string() + ": not a folder (a run directory of svgmotion run)");
  if (!fs::is_regular_file(run / "input.svg", ec))
    throw Error(run_in.string() + ": not a run directory (no input.svg; made by svgmotion run)");
  RunFiles f;
  f.run = run.filename().empty() ? run.parent_path() : run;
  f.fit = read_json(f.run / "fit.json");
  f.ranking = read_json(f.run / "ranking.json");
  f.command = read_json(f.run / ".svgmotion" / "command.json");
  f.motion = read_json(f.run / "motion.json");
  // The animation fit.json names (animation.failed.svg for a rejected fit), else what is there.
  for (const std::string& name : {text_of(f.fit, "animation"), std::string("animation.svg"), std::string("animation.failed.svg")})
    if (!name.empty() && name.find('/') == std::string::npos && fs::is_regular_file(f.run / name, ec)) {
      f.animation = f.run / name;
      break;
    }
  ReportResult result;
  Renderer renderer(o.device);
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">" + content_security_policy() +
                     "<title>svgmotion: " +
                     html_escape(f.run.filename().string()) + "</title>" + kStyle + "</head><body>\n";
  page += summary_section(f);
  page += motion_section(f.motion, motion_drawing(f, renderer, o, result.notes));
  page += player_section(f, o, result.notes);
  page += downloads_section(f.run);
  page += input_section(f, renderer, o, result.notes);
  page += candidates_section(f, o, result.notes);
  page += compare_section(f, renderer, o, result.notes);
  page += loss_section(f);
  page += timings_section(f);
  page += std::string(kScript) + "\n</body></html>\n";
  result.file = f.run / "report.html";
  write_file_atomic(result.file, page);
  result.bytes = page.size();
  return result;
}

}  // namespace svgm
