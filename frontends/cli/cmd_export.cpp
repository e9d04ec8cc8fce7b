// `svgmotion export RUN_DIR|FIT_DIR`: writes a finished fit's animation again from its
// checkpoint.bin (fit/output/animation_export.h) with other export settings, without fitting: the
// compact or full SVG, the Lottie, and clips rendered from the SVG.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "media/video_encoder.h"
#include "fit/output/animation_export.h"
#include "fit/fit_job.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm::cli {

namespace fs = std::filesystem;

int cmd_export(const std::vector<std::string>& argv) {
  const Args a = parse_args("export", argv, {"-o", "--output", "--precision", "--format", "--inbetweens", "--tolerance", "--fps", "--quality"},
                            {"--full", "--transparent"});
  if (a.positional.size() != 1)
    throw UsageError("export: expected one run or fit directory (svgmotion export RUN_DIR|FIT_DIR [-o OUT_DIR])");
  const fs::path dir = a.positional[0];
  const auto o = a.get("-o") ? a.get("-o") : a.get("--output");
  const fs::path out = o ? fs::path(*o) : dir;
  ExportSettings settings;
  settings.compact = !a.has("--full");
  settings.decimals = a.get_int("--precision", -1, 0, kMaxDecimals);
  settings.tolerance_1024 = a.get_double("--tolerance", settings.tolerance_1024);
  if (a.has("--tolerance") && !(settings.tolerance_1024 > 0 && settings.tolerance_1024 <= 64))
    throw Error("export: --tolerance wants pixels at 1024 px, more than 0 and at most 64");
  settings.inbetweens = a.get_int("--inbetweens", settings.inbetweens, 0, kMaxInbetweens);
  // Formats: every one named is written; clips are rendered from animation.svg, so it is written
  // with them.
  std::vector<std::string> clips;
  settings.svg = settings.lottie = false;
  std::stringstream list(a.get("--format").value_or("svg,lottie"));
  for (std::string f; std::getline(list, f, ',');) {
    if (f == "svg") settings.svg = true;
    else if (f == "lottie" || f == "dotlottie") settings.lottie = true;  // animation.json and its .lottie, together
    else if (f == "gif" || f == "mp4" || f == "webm" || f == "webp") clips.push_back(f), settings.svg = true;
    else throw Error("export: unknown format '" + f + "' (svg, lottie, dotlottie, gif, mp4, webm, webp)");
  }
  if (!settings.svg && !settings.lottie) throw Error("export: --format names no format (svg, lottie, dotlottie, gif, mp4, webm, webp)");
  // Clip settings, checked before anything is written. The frame rate defaults to the fit's
  // (the target video's), so a 24 fps animation is not resampled to 30.
  const bool has_fps = a.has("--fps");
  const double clip_fps = a.get_double("--fps", 0);
  if (has_fps && !(clip_fps >= 1 && clip_fps <= 240)) throw Error("export: --fps wants a frame rate in [1, 240]");
  const int quality = a.get_int("--quality", -1, 0, kMaxVp9Crf);
  const bool transparent = a.has("--transparent");
  auto has_clip = [&](const char* f) { return std::find(clips.begin(), clips.end(), f) != clips.end(); };
  if ((has_fps || a.has("--quality") || transparent) && clips.empty())
    throw Error("export: --fps, --quality and --transparent are for clips (--format gif, mp4, webm or webp)");
  if (a.has("--quality") && !has_clip("mp4") && !has_clip("webm"))
    throw Error("export: --quality is for mp4 and webm clips (a CRF, lower is better)");
  if (a.has("--quality") && has_clip("mp4") && quality > kMaxH264Crf)
    throw Error("export: --quality for mp4 (H.264) wants a CRF in 0..51");
  if (transparent && !has_clip("gif") && !has_clip("webm") && !has_clip("webp"))
    throw Error("export: --transparent is for gif, webm and webp clips (mp4's H.264 has no alpha)");
  const auto t0 = std::chrono::steady_clock::now();
  const ExportOutcome r = export_fit_directory(dir, out, settings);
  for (const std::string& w : r.warnings) log::warning("%s", w.c_str());
  std::string wrote;
  auto add = [&](const fs::path& p) {
    std::error_code ec;
    const auto size = fs::file_size(p, ec);
    wrote += (wrote.empty() ? "" : ", ") + p.filename().string() + " (" + std::to_string(ec ? 0 : (size + 512) / 1024) + " kB)";
  };
  if (settings.svg) add(r.svg);
  if (settings.lottie) add(fs::path(r.svg).replace_extension(".json")), add(fs::path(r.svg).replace_extension(".lottie"));
  for (const std::string& c : clips) {
    const fs::path clip = out / ("animation." + c);
    char fps[32];
    std::snprintf(fps, sizeof fps, "%.9g", has_fps ? clip_fps : r.fps);
    std::vector<std::string> args{r.svg.string(), "-o", clip.string(), "--fps", fps, "--quiet"};
    if (a.has("--quality") && (c == "mp4" || c == "webm")) args.insert(args.end(), {"--quality", std::to_string(quality)});
    if (transparent && c != "mp4") args.insert(args.end(), {"--background", "transparent"});
    if (const int rc = cmd_render(args); rc != 0) return rc;
    add(clip);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  log::info("svgmotion: exported from %s without fitting in %.2fs (%s, %d values per path%s): %s",
            (dir / "checkpoint.bin").c_str(), seconds, settings.compact && !r.full_fallback ? "compact" : "full", r.values_written,
            r.full_fallback ? (", " + tolerance_text(r)).c_str()
            : settings.compact ? (", " + std::to_string(r.stats.keys) + " keys kept, " + tolerance_text(r)).c_str() : "",
            wrote.c_str());
  return 0;
}

}  // namespace svgm::cli
