// report.html's motion section and the summary's caveat, from motion.json files written by hand:
// each planned action is a numbered row (verb, parts, amplitude in degrees or in % of the figure,
// direction, why), its parts outlined on the drawing in the row's colour (the figure's box for a
// whole-figure motion), the words not understood named (not those the lexicon read), the
// fallback sway said as a warning, and the fit's status not a plain "ok" when either happened.
// A whole page of such a run is written too, and every href and src in it must resolve: a data:
// URI or a file of the run directory.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "report/report_motion.h"
#include "report/report_page.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

// A man with an arm, a body and a backdrop (the backdrop is outside the figure's box); the plan
// waves the arm and hops; the prompt had one word nothing read and one the lexicon read.
json waving_man() {
  return json::parse(R"j({
    "source": "prompt", "prompt": "the man waves his <arm> and zorbles", "canvas": [200, 100], "keyframes": 9,
    "parts": [
      {"name": "body", "role": "root", "box": [50, 20, 90, 80], "why": "largest central part"},
      {"name": "arm<r>", "role": "upper limb", "box": [90, 10, 120, 40], "why": "named"},
      {"name": "sky", "role": "background", "box": [0, 0, 200, 100], "why": "fills the canvas"}],
    "plan": [
      {"verb": "wave", "motion": "swing", "parts": ["arm<r>"], "amplitude": 18.4, "unit": "degrees", "cycles": 2,
       "region": "", "one_sided": 0, "direction": "back and forth, clockwise first", "fallback": false,
       "why": "'the man waves his arm': wave moves the arms (arm<r>)"},
      {"verb": "hop", "motion": "hop", "parts": "whole figure", "amplitude": 0.0722, "unit": "figure heights", "cycles": 2,
       "region": "", "one_sided": 0, "direction": "up in an arc and back down", "fallback": false,
       "why": "'hops': hop moves the whole figure"}],
    "not_understood": ["man", "zorbles"], "readings": ["'man': biped, moves by itself as wave"],
    "warnings": [], "notes": []})j");
}

// A prompt with no motion word: plan_from_prompt's gentle sway of the figure.
json fallback_sway() {
  json m = waving_man();
  m["prompt"] = "it zorbles";
  m["not_understood"] = {"it", "zorbles"};
  m["readings"] = json::array();
  m["plan"] = json::parse(R"j([{"verb": "sway", "motion": "sway", "parts": "whole figure", "amplitude": 3, "unit": "degrees",
    "cycles": 1, "region": "", "one_sided": 0, "direction": "side to side, right first", "fallback": true,
    "why": "'(fallback)': sway moves the whole figure"}])j");
  m["warnings"] = {"no motion understood in the prompt (not understood: it, zorbles); the figure sways gently"};
  return m;
}

std::string read_text(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string percent_decoded(const std::string& url) {
  std::string out;
  for (size_t i = 0; i < url.size(); ++i)
    if (url[i] == '%' && i + 2 < url.size()) {
      out += static_cast<char>(std::stoi(url.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += url[i];
    }
  return out;
}

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("each planned action is a row with its parts outlined in its colour on the drawing") {
    const std::string s = motion_section(waving_man(), "data:image/png;base64,AAAA");
    CHECK(s.find("<q class=\"svgm-motion-prompt\">the man waves his &lt;arm&gt; and zorbles</q>") != std::string::npos);
    // Rows: number and colour, verb, parts, amplitude (degrees; a hop in % of the figure's
    // height), direction, cycles, why.
    CHECK(count(s, "<tr class=\"svgm-action\"") == 2);
    CHECK(s.find("data-action=\"1\"><td><span class=\"svgm-swatch\" style=\"background:#d62728\">1</span></td><td>wave<br><small>swing</small>"
                 "</td><td>arm&lt;r&gt;</td><td>18.4 \xC2\xB0</td><td>back and forth, clockwise first</td><td>2</td><td>"
                 "&#39;the man waves his arm&#39;: wave moves the arms (arm&lt;r&gt;)</td></tr>") != std::string::npos);
    CHECK(s.find("data-action=\"2\"><td><span class=\"svgm-swatch\" style=\"background:#1f77b4\">2</span></td><td>hop<br><small>hop</small>"
                 "</td><td>whole figure</td><td>7.22 % of the figure&#39;s height</td><td>up in an arc and back down</td>") !=
          std::string::npos);
    // The drawing, then the outlines: the arm's box in action 1's red; for the hop the figure's
    // box (body and arm, not the backdrop), 1.5 strokes (of 0.008 of 200) farther out, in blue.
    CHECK(s.find("<svg class=\"svgm-motion-parts\" width=\"260\" viewBox=\"0 0 200 100\"") != std::string::npos);
    CHECK(s.find("<image href=\"data:image/png;base64,AAAA\" width=\"200\" height=\"100\"") != std::string::npos);
    CHECK(count(s, "class=\"svgm-outline\"") == 2);
    CHECK(s.find("<rect class=\"svgm-outline\" data-action=\"1\" x=\"90\" y=\"10\" width=\"30\" height=\"30\" fill=\"none\" "
                 "stroke=\"#d62728\"") != std::string::npos);
    CHECK(s.find("<rect class=\"svgm-outline\" data-action=\"2\" x=\"47.6\" y=\"7.6\" width=\"74.8\" height=\"74.8\" fill=\"none\" "
                 "stroke=\"#1f77b4\"") != std::string::npos);
    // 'man' was read (a biped): only 'zorbles' is not understood. No fallback.
    CHECK(s.find("<p class=\"svgm-warn\" id=\"svgm-not-understood\">Not understood: zorbles <small>") != std::string::npos);
    CHECK(s.find("svgm-fallback") == std::string::npos);
    const MotionCaveat c = motion_caveat(waving_man());
    CHECK_FALSE(c.fallback);
    CHECK(c.line == "a word of the prompt not understood: zorbles; the motion follows the rest");
  }

  TEST_CASE("a region that bends is outlined dashed on its part; repeated elements have no box to outline") {
    json m = waving_man();
    m["plan"] = json::parse(R"j([
      {"verb": "wave", "motion": "swing", "parts": ["body"], "region": "sides", "amplitude": 20, "unit": "degrees",
       "direction": "back and forth, the two sides in turn", "why": "no separate arms: the sides of body bend"},
      {"verb": "fall", "motion": "fall", "parts": "12 repeated elements", "amplitude": 1, "unit": "canvas heights",
       "direction": "down, each element in its own phase", "why": "12 drops"}])j");
    const std::string s = motion_section(m, "data:image/png;base64,AAAA");
    CHECK(s.find("</td><td>the sides of body</td><td>20 \xC2\xB0</td><td>back and forth, the two sides in turn</td>") != std::string::npos);
    CHECK(s.find("<rect class=\"svgm-outline\" data-action=\"1\" x=\"50\" y=\"20\" width=\"40\" height=\"60\" fill=\"none\" "
                 "stroke=\"#d62728\" stroke-width=\"1.6\" stroke-dasharray=\"4.8\"/>") != std::string::npos);
    CHECK(s.find("</td><td>12 repeated elements</td><td>100 % of the canvas height</td>") != std::string::npos);
    CHECK(s.find("data-action=\"2\" x=") == std::string::npos);
  }

  TEST_CASE("a plan from the llm planner names the model and shows its plan; the planner's fallback is a warning") {
    json m = waving_man();
    m["source"] = "llm";
    m["planner"] = {{"planner", "llm"}, {"source", "llm"}, {"model", "qwen<vl>"}, {"plan", "wave:arm<r>, hop:whole"}, {"answer", "x"}};
    const std::string s = motion_section(m, "");
    CHECK(s.find("<p>Planned from a vision model&#39;s plan (planner llm, qwen&lt;vl&gt;) for <q class=\"svgm-motion-prompt\">") !=
          std::string::npos);
    CHECK(s.find("<p>Its plan: <code class=\"svgm-llm-plan\">wave:arm&lt;r&gt;, hop:whole</code></p>") != std::string::npos);
    CHECK(s.find("svgm-planner-fallback") == std::string::npos);
    json off = waving_man();
    off["planner"] = {{"planner", "llm"}, {"source", "offline"}, {"fallback", "HTTP 500 from <url>"}};
    const std::string f = motion_section(off, "");
    CHECK(f.find("<p>Planned from the prompt <q") != std::string::npos);
    CHECK(f.find("<p class=\"svgm-warn\" id=\"svgm-planner-fallback\">The llm planner gave no plan (HTTP 500 from &lt;url&gt;): "
                 "planned offline from the prompt's words.</p>") != std::string::npos);
    CHECK(f.find("svgm-llm-plan") == std::string::npos);
  }

  TEST_CASE("the fallback sway is said as a warning, its row marked; every word understood is no caveat") {
    const std::string s = motion_section(fallback_sway(), "data:image/png;base64,AAAA");
    CHECK(s.find("<p class=\"svgm-warn\" id=\"svgm-fallback\">No motion word in the prompt was understood: the figure only sways "
                 "gently (a fallback, not what the prompt asked).") != std::string::npos);
    CHECK(s.find("Not understood: it, zorbles") != std::string::npos);
    CHECK(s.find("<tr class=\"svgm-action svgm-warn-row\" data-action=\"1\">") != std::string::npos);
    CHECK(s.find("<td><b>fallback</b>: no motion word understood, so the whole figure sways gently</td>") != std::string::npos);
    CHECK(s.find("svgm-motion-warnings") == std::string::npos);  // its warning is the paragraph above
    CHECK(s.find("class=\"svgm-outline\" data-action=\"1\" x=\"50\" y=\"10\" width=\"70\" height=\"70\"") != std::string::npos);
    const MotionCaveat c = motion_caveat(fallback_sway());
    CHECK(c.fallback);
    CHECK(c.line == "no motion word in the prompt was understood (it, zorbles): the figure only sways gently, a fallback");
    // A motion.json written before "fallback": its warning says it.
    json old = fallback_sway();
    old["plan"][0].erase("fallback");
    CHECK(motion_caveat(old).fallback);
    json clear = waving_man();
    clear["not_understood"] = {"man"};
    CHECK(motion_caveat(clear).line.empty());
    CHECK(motion_caveat(json()).line.empty());
    // No drawing: the rows without outlines.
    const std::string bare = motion_section(waving_man(), "");
    CHECK(count(bare, "<tr class=\"svgm-action\"") == 2);
    CHECK(bare.find("svgm-outline") == std::string::npos);
  }

  TEST_CASE("a fitted run whose motion fell back: the status is no plain ok, and every link resolves") {
    test::TempDir dir("svgm_report_motion");
    const fs::path run = dir.path / "run";
    fs::create_directories(run / "candidates");
    std::ofstream(run / "input.svg") << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\">"
                                        "<rect x=\"50\" y=\"20\" width=\"40\" height=\"60\" fill=\"#c00\"/></svg>";
    std::ofstream(run / "motion.json") << fallback_sway().dump();
    std::ofstream(run / "fit.json") << R"({"status": "ok", "keyframes": 4, "iterations": 40, "seconds": 1.5, "device": "cpu"})";
    std::ofstream(run / "log.txt") << "log\n";
    std::ofstream(run / "candidates" / "00.mp4") << "not a video";
    std::ofstream(run / "odd name #1.txt") << "a file whose name needs escaping in a link";
    ReportOptions o;
    o.thumb_width = 32;
    write_report(run, o);
    const std::string page = read_text(run / "report.html");
    CHECK(page.find("Fit: <b class=\"svgm-status-warn\">ok, but the motion is a fallback</b>") != std::string::npos);
    CHECK(count(page, "svgm-status-ok") == 1);  // only in the style sheet
    CHECK(page.find("<p class=\"svgm-caveat\" id=\"svgm-caveat\">The motion: no motion word in the prompt was understood (it, "
                    "zorbles): the figure only sways gently, a fallback.</p>") != std::string::npos);
    // The motion comes right after the summary, before the player and the outputs.
    const size_t motion = page.find("<section id=\"svgm-motion\">");
    CHECK(motion != std::string::npos);
    CHECK(motion < page.find("<section id=\"svgm-player\">"));
    CHECK(page.find("<section id=\"svgm-player\">") < page.find("<section id=\"svgm-downloads\">"));
    CHECK(count(page, "class=\"svgm-outline\"") == 1);
    CHECK(page.find("<image href=\"data:image/png;base64,") != std::string::npos);  // the drawing, rendered
    // Every href and src: a data: URI, or a file in the run directory (percent-decoded).
    const std::regex link("(?:href|src)=\"([^\"]*)\"");
    int files = 0, data = 0;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), link); it != std::sregex_iterator(); ++it) {
      const std::string url = (*it)[1];
      if (url.rfind("data:", 0) == 0) {
        ++data;
        continue;
      }
      const std::string path = percent_decoded(url);
      INFO("link: ", url);
      CHECK(path.find("..") == std::string::npos);
      CHECK(path.find(':') == std::string::npos);
      CHECK(fs::is_regular_file(run / path));
      ++files;
    }
    CHECK(files == 6);  // fit.json, input.svg, log.txt, motion.json, odd name #1.txt, candidates/00.mp4
    CHECK(data >= 2);   // the drawing under the outlines, the input
    CHECK(page.find("href=\"odd%20name%20%231.txt\"") != std::string::npos);
  }
}
