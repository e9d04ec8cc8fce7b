// The parts of report.html that can be checked by hand: escaping of text from files, the shell
// quoting of the "use this one" command and how it is made from the recorded command, the
// charts' geometry, and the animation made safe to inline (no script, a viewBox, full size).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "error_of.h"
#include "report/html_text.h"
#include "report/inline_svg.h"
#include "report/report_charts.h"
#include "report/rerun_command.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

TEST_SUITE("report") {
  TEST_CASE("text from files is escaped for element content and attributes alike") {
    CHECK(html_escape("<b id=\"x\">&amp;</b> it's") == "&lt;b id=&quot;x&quot;&gt;&amp;amp;&lt;/b&gt; it&#39;s");
    CHECK(html_escape("caf\xc3\xa9 01.mp4") == "caf\xc3\xa9 01.mp4");  // UTF-8 and plain names unchanged
    CHECK(html_number(0.0123456) == "0.01235");
    CHECK(html_number(NAN) == "-");
  }

  TEST_CASE("shell quoting leaves plain words and quotes the rest for sh") {
    CHECK(shell_quote("stages.ranker.choose=01.mp4") == "stages.ranker.choose=01.mp4");
    CHECK(shell_quote("/tmp/run") == "/tmp/run");
    CHECK(shell_quote("the man waves") == "'the man waves'");
    CHECK(shell_quote("it's") == "'it'\\''s'");
    CHECK(shell_quote("$HOME") == "'$HOME'");
    CHECK(shell_quote("") == "''");
  }

  TEST_CASE("the command for another candidate is the recorded one without --from, with the choice") {
    test::TempDir dir("svgm_report_cmd");
    CHECK_FALSE(choose_command(dir.path, "01.mp4"));  // nothing recorded: no command made up
    fs::create_directories(dir.path / ".svgmotion");
    const nlohmann::json rec = {{"cwd", "/home/a b"},
                                {"exe", "/usr/bin/svgmotion"},
                                {"command", "run"},
                                {"args", {"--input", "man.svg", "--from", "fitter", "--prompt", "it's", "-o", "r",
                                          "--from=video", "stages.ranker.choose=00.mp4", "stages.fitter.iterations=30"}}};
    std::ofstream(dir.path / ".svgmotion" / "command.json") << rec.dump();
    const auto cmd = choose_command(dir.path, "02.mp4");
    REQUIRE(cmd);
    CHECK(*cmd == "cd '/home/a b' && /usr/bin/svgmotion run --input man.svg --prompt 'it'\\''s' -o r "
                  "stages.fitter.iterations=30 stages.ranker.choose=02.mp4");
  }

  TEST_CASE("a recorded command round-trips through record_run_command") {
    test::TempDir dir("svgm_report_rec");
    record_run_command(dir.path, {"--input", "x.svg", "-o", "run"}, "a bird flies");
    std::ifstream in(dir.path / ".svgmotion" / "command.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    CHECK(j["args"] == nlohmann::json({"--input", "x.svg", "-o", "run"}));
    CHECK(j["prompt"] == "a bird flies");
    CHECK(j["cwd"] == fs::current_path().string());
    const auto cmd = choose_command(dir.path, "03.mp4");
    REQUIRE(cmd);
    CHECK(cmd->ends_with(" run --input x.svg -o run stages.ranker.choose=03.mp4"));
  }

  TEST_CASE("a line chart maps the data's range onto the plot area") {
    // Plot area of a 560 x 220 chart: x 64..548, y 26..182; a linear axis starts at zero.
    const std::string s = line_chart_svg({0, 10, 20}, {0, 5, 10}, {"t", "x", "y"}, false);
    CHECK(s.find("d=\"M64.0 182.0L306.0 104.0L548.0 26.0\"") != std::string::npos);
    // Log axis: 1, 10, 100 are evenly spaced; a non-finite value is skipped.
    const std::string l = line_chart_svg({0, 1, 2, 3}, {1, 10, NAN, 100}, {"t", "x", "y"}, true);
    CHECK(l.find("d=\"M64.0 182.0L225.3 104.0L548.0 26.0\"") != std::string::npos);
    CHECK(l.find("log scale") != std::string::npos);
    CHECK(line_chart_svg({}, {}, {"t", "x", "y"}, true).empty());
    // Titles are text from us, but escaped all the same.
    CHECK(line_chart_svg({0, 1}, {1, 2}, {"a<b", "x", "y"}, false).find(">a&lt;b</text>") != std::string::npos);
  }

  TEST_CASE("a bar chart draws one bar per finite positive value, scaled to the largest") {
    const std::string s = bar_chart_svg({2, NAN, 4}, {"t", "keyframe", "loss"});
    size_t bars = 0;
    for (size_t at = s.find("class=\"svgm-bar\""); at != std::string::npos; at = s.find("class=\"svgm-bar\"", at + 1)) ++bars;
    CHECK(bars == 2);
    // Slots of (548 - 64) / 3 px; the largest bar (4) fills the plot height 26..182.
    CHECK(s.find("y=\"26.0\" width=\"112.9\" height=\"156.0\"") != std::string::npos);
    CHECK(s.find("y=\"104.0\" width=\"112.9\" height=\"78.0\"") != std::string::npos);
    CHECK(bar_chart_svg({}, {"t", "x", "y"}).empty());
  }

  TEST_CASE("the animation is inlined without scripts, with a viewBox, at its box's size") {
    test::TempDir dir("svgm_report_svg");
    const fs::path f = dir.path / "a.svg";
    std::ofstream(f) << "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200px\" "
                        "height=\"100\" onload=\"alert(1)\"><script>alert(2)</script><a href=\" JavaScript:alert(3)\">"
                        "<path id=\"p\" d=\"M0 0H10V10Z\" onclick=\"x()\"><animate attributeName=\"d\" dur=\"1s\" "
                        "values=\"M0 0H10V10Z;M0 0H20V20Z\"/></path></a></svg>";
    const InlinedSvg inlined = inline_svg(f);
    const std::string& s = inlined.markup;
    CHECK(s.rfind("<svg ", 0) == 0);
    CHECK(s.find("<?xml") == std::string::npos);
    CHECK(s.find("script") == std::string::npos);
    CHECK(s.find("alert") == std::string::npos);
    CHECK(s.find("onclick") == std::string::npos);
    CHECK(s.find("viewBox=\"0 0 200 100\"") != std::string::npos);
    CHECK(s.find("width=\"100%\" height=\"100%\"") != std::string::npos);
    CHECK(s.find("<animate attributeName=\"d\" dur=\"1s\" values=\"M0 0H10V10Z;M0 0H20V20Z\"></animate>") != std::string::npos);
    CHECK(inlined.dropped == "2 on* attributes, 1 <script>, 1 href outside the drawing");
    std::ofstream(dir.path / "b.svg") << "<html/>";
    CHECK(test::error_of([&] { inline_svg(dir.path / "b.svg"); }) == (dir.path / "b.svg").string() + ": not an SVG document (no <svg> root)");
  }
}
