// The outputs section of report.html (see report_downloads.h).
#include "report/report_downloads.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "report/html_text.h"
#include "generators/candidates.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// What each of the run's own files is; anything else is listed by its name
// alone.
const char *what_is(const std::string &name) {
  struct Known {
    const char *name;
    const char *what;
  };
  static constexpr Known kKnown[] = {
      {"animation.svg",
       "the animated SVG (SMIL): your drawing with its motion"},
      {"animation.failed.svg",
       "the animation the result gate rejected (fit.json says why)"},
      {"animation.json", "the animation as Lottie"},
      {"animation.failed.json", "the rejected animation as Lottie"},
      {"animation.lottie", "the animation as dotLottie"},
      {"animation.gif", "the animation as a GIF"},
      {"animation.mp4", "the animation as an MP4 video"},
      {"animation.webm", "the animation as a WebM video"},
      {"preview.mp4", "the target beside the fit at every keyframe"},
      {"target.mp4", "the video the fit followed"},
      {"input.svg", "your drawing, as given"},
      {"grouped.svg", "your drawing with its parts named"},
      {"recolored.svg", "the drawing in distinct colours, one per part"},
      {"recolored.png", "what the video model was shown"},
      {"layered.svg", "the parts in depth order"},
      {"fit.json", "the fit's numbers: losses, keyframes, the result gate"},
      {"motion.json", "the motion plan"},
      {"ranking.json", "the ranker's scores"},
      {"resolved.yaml", "the config this run used, every key"},
      {"log.txt", "every message of the run, with its command line"},
      {"checkpoint.bin", "the fit's state (a re-run resumes from it)"},
  };
  for (const Known &k : kKnown)
    if (name == k.name)
      return k.what;
  return "";
}

std::string size_text(uintmax_t bytes) {
  char buf[32];
  if (bytes < 1024)
    std::snprintf(buf, sizeof buf, "%ju B", bytes);
  else if (bytes < 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f KB", bytes / 1024.0);
  else
    std::snprintf(buf, sizeof buf, "%.1f MB", bytes / (1024.0 * 1024.0));
  return buf;
}

} // namespace

std::string url_path(const std::string &relative) {
  static const char *hex = "0123456789ABCDEF";
  std::string out;
  for (const char ch : relative) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' ||
        c == '/')
      out += ch;
    else
      out += std::string("%") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

std::string downloads_section(const fs::path &run) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto &e : fs::directory_iterator(run, ec)) {
    const std::string n = e.path().filename().string();
    if (n.empty() || n[0] == '.' || n == "report.html" ||
        !e.is_regular_file(ec))
      continue;
    files.push_back(n);
  }
  std::sort(files.begin(), files.end(),
            [](const std::string &a, const std::string &b) {
              // The animation first: it is what is shipped.
              const bool ka = a.rfind("animation.", 0) == 0,
                         kb = b.rfind("animation.", 0) == 0;
              return ka != kb ? ka : a < b;
            });
  for (const fs::path &c : list_candidates(run / "candidates"))
    if (fs::is_regular_file(c, ec))
      files.push_back("candidates/" + c.filename().string());
  std::string s =
      "<p>Every file of the run directory, linked where it lies (keep "
      "report.html beside them).</p>"
      "<table class=\"svgm-downloads\"><tr><th>file</th><th>size</th><th>what "
      "it is</th></tr>";
  for (const std::string &f : files) {
    const uintmax_t bytes = fs::file_size(run / f, ec);
    s += "<tr><td><a href=\"" + html_escape(url_path(f)) + "\" download>" +
         html_escape(f) + "</a></td><td>" +
         (ec ? std::string("?") : size_text(bytes)) + "</td><td>" +
         html_escape(f.rfind("candidates/", 0) == 0 ? "a candidate video"
                                                    : what_is(f)) +
         "</td></tr>";
  }
  s += "</table>";
  if (files.empty())
    s = "<p class=\"svgm-missing\">No files in the run directory yet.</p>";
  return "<section id=\"svgm-downloads\"><h2>Outputs</h2>" + s + "</section>\n";
}

} // namespace svgm
