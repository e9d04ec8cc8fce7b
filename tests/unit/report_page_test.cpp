// report.html of a run stopped before fitting (every candidate flagged), made by the test: a
// run directory with input.svg, two candidates (.mp4 names with bytes that are no video),
// ranking.json with a reason holding markup, and a recorded command. The page must still be
// written, escape the ranker's text, mark the chosen candidate "chosen" (not "fitted"), offer
// the command for every candidate, and say what is missing in the sections it cannot fill.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "error_of.h"
#include "net/base64.h"
#include "report/report_page.h"
#include "report/rerun_command.h"
#include "report/sha256.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;

namespace {

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_SUITE("report") {
  TEST_CASE("a run stopped before fitting gets a page with its candidates and what is missing") {
    test::TempDir dir("svgm_report_page");
    const fs::path run = dir.path / "run";
    fs::create_directories(run / "candidates");
    std::ofstream(run / "input.svg") << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"20\">"
                                        "<rect width=\"20\" height=\"10\" fill=\"#c00\"/></svg>";
    std::ofstream(run / "candidates" / "00.mp4") << "not a video";
    std::ofstream(run / "candidates" / "01.mp4") << "not a video either";
    std::ofstream(run / "ranking.json")
        << R"({"chosen": "01.mp4", "reason": "lowest <script>alert(1)</script>",
               "candidates": [{"name": "01.mp4", "score": 0.5, "defects": ["colour drift & <blobs>"]},
                              {"name": "00.mp4", "score": 0.7, "defects": ["jumps"]}]})";
    record_run_command(run, {"--input", "man.svg", "-o", "run"}, "it <waves>");

    ReportOptions o;
    o.thumb_width = 32;
    const ReportResult r = write_report(run, o);
    CHECK(r.file == run / "report.html");
    std::ifstream in(r.file);
    const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(page.size() == r.bytes);
    for (const char* id : {"svgm-summary", "svgm-player", "svgm-input", "svgm-candidates", "svgm-compare", "svgm-losses",
                           "svgm-timings"})
      CHECK(count(page, std::string("id=\"") + id + "\"") == 1);
    // The ranker's text is shown, never run: the page's only script is its own.
    CHECK(count(page, "<script>") == 1);
    CHECK(page.find("lowest &lt;script&gt;alert(1)&lt;/script&gt;") != std::string::npos);
    CHECK(page.find("colour drift &amp; &lt;blobs&gt;") != std::string::npos);
    CHECK(page.find("<q id=\"svgm-prompt\">it &lt;waves&gt;</q>") != std::string::npos);
    // Both candidates embedded (the bytes are within the budget), the chosen one marked chosen.
    CHECK(count(page, "src=\"data:video/mp4;base64,") == 2);
    CHECK(page.find("svgm-candidate svgm-chosen\" data-name=\"01.mp4\"><h3>01.mp4 <span class=\"svgm-badge\">chosen</span>") !=
          std::string::npos);
    CHECK(page.find(">fitted<") == std::string::npos);
    // Nothing is fitted, so each candidate (the chosen one too) has its command.
    CHECK(count(page, "class=\"svgm-use\"") == 2);
    CHECK(page.find(" run --input man.svg -o run stages.ranker.choose=00.mp4</pre>") != std::string::npos);
    CHECK(page.find(" run --input man.svg -o run stages.ranker.choose=01.mp4</pre>") != std::string::npos);
    CHECK(page.find("No animation.svg in the run directory yet.") != std::string::npos);
    CHECK(page.find("No fit.json yet.") != std::string::npos);
    CHECK(page.find("data:image/png;base64,") != std::string::npos);  // the input, drawn
    // The policy comes first in <head> and lets run only the page's own script, by its hash.
    const size_t open = page.find("<script>") + 8, close = page.find("</script>");
    const std::string policy = "<head><meta charset=\"utf-8\"><meta http-equiv=\"Content-Security-Policy\" content=\""
                               "default-src 'none'; script-src 'sha256-" + base64(sha256(page.substr(open, close - open))) +
                               "'; style-src 'unsafe-inline'; img-src data:; media-src data:; base-uri 'none'; "
                               "form-action 'none'\"><title>";
    CHECK(page.find(policy) != std::string::npos);
  }

  TEST_CASE("a folder that is not a run directory is refused in one line") {
    test::TempDir dir("svgm_report_none");
    CHECK(test::error_of([&] { write_report(dir.path); }) ==
          dir.path.string() + ": not a run directory (no input.svg; made by svgmotion run)");
    CHECK_FALSE(fs::exists(dir.path / "report.html"));
  }
}
