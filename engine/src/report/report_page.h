// report.html: one self-contained page (inline CSS and script, images and videos as data:
// URIs, no server, nothing fetched) showing what a run did, written into the run directory.
//
// Sections, each an element with a fixed id (tests and readers find them): every file of the
// run with its size and a relative link (svgm-downloads), the animation itself with play/pause
// and a scrubber beside the Lottie file as librlottie draws it (svgm-player), the input drawing and its recoloured copy
// (svgm-input), every candidate video (frames in the drawing's own colours, the video as made folded) with
// the ranker's scores and reasons, the fitted one
// marked and for the others the exact command that fits them instead (svgm-candidates), the
// target's keyframes beside the fit at the same times (svgm-compare), the loss over
// iterations and per keyframe (svgm-losses), and the seconds of every stage (svgm-timings).
// A section whose files are missing (a run stopped before fitting) says what is missing.
//
// Everything taken from files is escaped (report/html_text.h); the animation is inlined from an
// allow-list (report/inline_svg.h), what it leaves out named in a note and on the page. A
// Content-Security-Policy, first in <head>, lets run only the page's own script (by its hash)
// and load only data: URIs. The page is written under a temporary name and renamed.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace svgm {

struct ReportOptions {
  std::string device = "auto";  // OpenCL device for the thumbnails (our renderer)
  int thumb_width = 256;        // width of the input and keyframe pictures, px
  int player_width = 360;       // CSS width of the animation's box, px
  // Candidate videos are embedded until their bytes reach this; the rest are named, not
  // embedded (procedural candidates are 0.1-0.5 MB each; a hosted model's can be far larger).
  size_t max_video_bytes = 24u << 20;
  // Frames of the Lottie file drawn beside the animation (about 10 KB each at 360 px).
  int max_lottie_frames = 60;
};

struct ReportResult {
  std::filesystem::path file;
  size_t bytes = 0;
  std::vector<std::string> notes;  // what was left out and why (one line each)
};

// Writes <run>/report.html. Throws svgm::Error when `run` is not a run directory (no
// input.svg) or the page cannot be written; a missing or unreadable part becomes a note in
// its section instead.
ReportResult write_report(const std::filesystem::path& run, const ReportOptions& options = {});

}  // namespace svgm
