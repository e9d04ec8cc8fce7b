// Writing a fit's animation files, at the end of a fit or again from its checkpoint (see
// animation_export.h).
#include "fit/output/animation_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <iterator>
#include <nlohmann/json.hpp>

#include "export/lottie_writer.h"
#include "export/smil_clock.h"
#include "fit/output/checkpoint.h"
#include "fit/output/tolerance_choice.h"
#include "svg/document_order.h"
#include "fit/optimise/inbetween.h"
#include "fit/plan/segment_split.h"
#include "run/run_directory.h"
#include "raster/raster_plan.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

std::string fit_result_json(const FitResult& r) {
  const nlohmann::json j = {{"svg", r.svg},
                            {"export_into", r.export_into},
                            {"export_name", r.export_name},
                            {"max_segment", r.max_segment},
                            {"rejected", r.rejected},
                            {"keyframes", r.timing.keyframes},
                            {"key_times", r.timing.key_times},
                            {"duration_s", r.timing.duration_s},
                            {"loop", loop_mode_name(r.timing.loop)},
                            {"close_loop", r.timing.close_loop},
                            {"fps", r.fps},
                            {"source_frames", r.source_frames},
                            {"n_cp", r.n_cp}};
  return json_text(j);
}

FitResult fit_result_from_json(const std::string& text, const std::string& what) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  FitResult r;
  try {
    if (!j.is_object()) throw Error("");
    r.svg = j.at("svg").get<std::string>();
    r.export_into = j.at("export_into").get<std::string>();
    r.export_name = j.at("export_name").get<std::string>();
    r.max_segment = j.at("max_segment").get<double>();
    r.rejected = j.at("rejected").get<bool>();
    r.timing.keyframes = j.at("keyframes").get<int>();
    r.timing.key_times = j.at("key_times").get<std::vector<double>>();
    r.timing.duration_s = j.at("duration_s").get<double>();
    r.timing.loop = parse_loop_mode(j.at("loop").get<std::string>(), "loop");
    r.timing.close_loop = j.at("close_loop").get<bool>();
    r.fps = j.at("fps").get<double>();
    r.source_frames = j.at("source_frames").get<int>();
    r.n_cp = j.at("n_cp").get<int>();
  } catch (const std::exception&) {
    throw Error(what + ": the fit's result does not read (damaged checkpoint)");
  }
  if (r.timing.keyframes < 1 || r.source_frames < 2 || r.n_cp < 0 ||
      r.timing.key_times.size() != static_cast<size_t>(r.timing.keyframes))
    throw Error(what + ": the fit's result does not read (damaged checkpoint)");
  return r;
}

ExportDocument export_document(const Scene& as_read, const SplitPlan& split, const std::string& fitted_name,
                               const std::string& export_into) {
  ExportDocument d;
  if (export_into.empty()) {
    d.scene = split_scene(as_read, split);
    d.into = fitted_name;
    return d;
  }
  d.into = export_into;
  d.scene = read_svg_file(d.into);
  const std::vector<int> match = match_paths(as_read, d.scene, fitted_name);
  ExportMap map;
  map.fitted_of.assign(d.scene.paths.size(), -1);
  bool reordered = false;
  for (size_t j = 0; j < match.size(); ++j) {
    map.fitted_of[static_cast<size_t>(match[j])] = static_cast<int>(j);
    reordered = reordered || match[j] != static_cast<int>(j);
  }
  if (reordered) map.order = match;
  for (size_t i = 0; i < d.scene.paths.size(); ++i)
    if (map.fitted_of[i] >= 0) d.scene.paths[i] = split_path(d.scene.paths[i], split[static_cast<size_t>(map.fitted_of[i])]);
  d.map = std::move(map);
  return d;
}

std::string tolerance_text(const ExportOutcome& o) {
  char text[256];
  if (o.full_fallback)
    std::snprintf(text, sizeof text, "no tolerance keeps %g dB of the full export (worst %.1f dB at %g px at 1024): wrote it in full",
                  kCompactTargetDb + kCompactMarginDb, o.tolerance_db, o.tolerance_1024);
  else if (o.tolerance_db == 0) std::snprintf(text, sizeof text, "tolerance %g px at 1024 (given)", o.tolerance_1024);
  else if (std::isinf(o.tolerance_db)) std::snprintf(text, sizeof text, "tolerance %g px at 1024 (renders as the full export)", o.tolerance_1024);
  else if (o.residual_scale != 1)
    std::snprintf(text, sizeof text, "tolerance %g px at 1024, residual shapes %g x (worst %.1f dB of the full export)",
                  o.tolerance_1024, o.residual_scale, o.tolerance_db);
  else std::snprintf(text, sizeof text, "tolerance %g px at 1024 (worst %.1f dB of the full export)", o.tolerance_1024,
                     o.tolerance_db);
  std::string line = text;
  if (o.lottie_measured && o.lottie_db < kCompactTargetDb + kCompactMarginDb)
    std::snprintf(text, sizeof text, "; animation.json in full (worst %.1f dB in librlottie)", o.lottie_db);
  else if (o.lottie_measured)
    std::snprintf(text, sizeof text, "; animation.json %g px, residual %g x (worst %.1f dB in librlottie)",
                  o.lottie_tolerance_1024, o.lottie_residual_scale, o.lottie_db);
  else if (o.tolerance_db != 0 && !o.full_fallback)
    std::snprintf(text, sizeof text, "; animation.json at %g", lottie_tolerance(o.tolerance_1024));
  else text[0] = 0;
  return line + text;
}

ExportOutcome write_animation_files(const FitResult& result, const ExportSettings& settings, const ExportDocument& doc,
                                    const RasterPlan& plan, const fs::path& anim,
                                    const std::function<std::optional<PathMotion>(const std::vector<double>&,
                                                                                  const std::vector<double>&)>& group_motion) {
  ExportOutcome outcome;
  if (plan.n_cp != result.n_cp) throw Error("internal: the fit's control points do not match the plan");
  // What is written: the keyframes (a closed loop's last one is its first) and smooth
  // in-betweens at the target's frames between them (inbetween.h).
  const int N = std::max(2, result.source_frames);
  const size_t per_key = static_cast<size_t>(plan.n_cp) * 2;
  std::vector<double> frame_times;
  for (int i = 0; i < N; ++i) frame_times.push_back(static_cast<double>(i) / (N - 1));
  const InBetween written = in_between(result.points, result.timing.key_times, per_key, frame_times,
                                       settings.inbetweens, result.timing.close_loop);
  AnimationTiming wt = result.timing;
  wt.keyframes = static_cast<int>(written.times.size());
  wt.key_times = written.times;
  wt.close_loop = false;  // in_between already wrote the first keyframe's shape last
  outcome.values_written = wt.keyframes;
  outcome.fps = result.fps;
  outcome.svg = anim;
  const ExportMap* map = doc.map ? &*doc.map : nullptr;
  const double px_per_1024 = std::max(doc.scene.width, doc.scene.height) / 1024.0;
  auto write_compact_svg = [&](const fs::path& file, double tolerance_1024, CompactStats* stats, double residual_scale = 1) {
    CompactExport ce;
    ce.decimals = settings.decimals;
    ce.tolerance_px = tolerance_1024 * px_per_1024;
    ce.residual_scale = residual_scale;
    return write_compact_animation_svg(doc.into, doc.scene, plan, written.points, wt, file, map, ce, stats);
  };
  // The tolerance measured per drawing (tolerance_choice.h) unless one is given.
  outcome.tolerance_1024 = settings.tolerance_1024;
  bool compact = settings.compact;
  if (settings.compact && !(settings.tolerance_1024 > 0)) {
    const ToleranceChoice choice = choose_compact_tolerance(
        anim,
        [&](const fs::path& file) {
          write_animation_svg(doc.into, doc.scene, plan, written.points, wt, file, map, kDefaultDecimals, nullptr);
        },
        [&](const fs::path& file, double tolerance_1024) { write_compact_svg(file, tolerance_1024, nullptr); },
        [&](const fs::path& file, double tolerance_1024, double scale) {
          write_compact_svg(file, tolerance_1024, nullptr, scale);
        });
    outcome.tolerance_1024 = choice.tolerance_1024;
    outcome.residual_scale = choice.residual_scale;
    outcome.tolerance_db = choice.worst_db;
    // No compact file holds the target (a fit of two values, whose full export blends the
    // points along chords where the compact one turns along arcs): the full export is the
    // cheapest that does.
    if (choice.worst_db < kCompactTargetDb + kCompactMarginDb) {
      compact = false;
      outcome.full_fallback = true;
    }
    for (const ToleranceTrial& t : choice.trials)
      log::debug("export: compact tolerance %g px at 1024 (residual %g x): worst %.2f dB of the full export", t.tolerance_1024,
                 t.residual_scale, t.worst_db);
  }
  const double tolerance_px = outcome.tolerance_1024 * px_per_1024;
  auto name_line = [&](std::string line) {
    if (!result.export_name.empty() && line.rfind(doc.into.string(), 0) == 0)
      line = result.export_name + line.substr(doc.into.string().size());
    return line;
  };
  if (settings.svg) {
    std::vector<std::string> w;
    if (compact) {
      w = write_compact_svg(anim, outcome.tolerance_1024, &outcome.stats, outcome.residual_scale);
    } else {
      std::optional<PathMotion> motion;
      if (group_motion) motion = group_motion(written.times, frame_times);
      w = write_animation_svg(doc.into, doc.scene, plan, written.points, wt, anim, map,
                              settings.decimals >= 0 ? settings.decimals : kDefaultDecimals, motion ? &*motion : nullptr);
    }
    for (const std::string& line : w) outcome.warnings.push_back(name_line(line));
    // The fit's frame rate on the root, so that `render` makes a clip of it at that rate.
    std::ifstream in(anim, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    write_file_atomic(anim, with_frame_rate(text, anim.string(), result.fps));
  }
  if (settings.lottie) {
    const fs::path json = fs::path(anim).replace_extension(".json");
    LottieOptions lottie;
    lottie.fps = result.fps;
    lottie.decimals = settings.decimals >= 0 || compact ? settings.decimals : kDefaultDecimals;
    lottie.compact = compact;
    lottie.tolerance_px = tolerance_px;
    lottie.residual_scale = outcome.residual_scale;
    lottie.name = doc.into.filename().string();
    std::error_code ec;
    if (fs::exists(anim, ec)) lottie.exported_svg = anim;  // gradients follow their shapes as animation.svg draws them
    const bool measured = settings.compact && !(settings.tolerance_1024 > 0);
    // Measured on its own, in a Lottie player (tolerance_choice.h), when the build has one and
    // it can draw the file (a clip of a frame or two has no duration for rlottie).
    std::optional<ToleranceChoice> choice;
    if (const DrawerMaker draw = measured ? lottie_drawer() : nullptr) {
      auto write_json = [&](const fs::path& file, bool compact_json, double tolerance_1024, double scale) {
        LottieOptions o = lottie;
        o.compact = compact_json;
        o.decimals = compact_json ? settings.decimals : kDefaultDecimals;
        o.tolerance_px = tolerance_1024 * px_per_1024;
        o.residual_scale = scale;
        write_lottie(file, doc.scene, plan, written.points, wt, o, map);
      };
      try {
        choice = choose_compact_tolerance(
            json, [&](const fs::path& file) { write_json(file, false, 0, 1); },
            [&](const fs::path& file, double tolerance_1024) { write_json(file, true, tolerance_1024, 1); },
            [&](const fs::path& file, double tolerance_1024, double scale) { write_json(file, true, tolerance_1024, scale); },
            draw);
      } catch (const Error& e) {  // a write that failed fails again below
        log::debug("export: animation.json not measured in librlottie (%s)", e.what());
      }
    }
    if (choice) {
      for (const ToleranceTrial& t : choice->trials)
        log::debug("export: animation.json at %g px at 1024 (residual %g x): worst %.2f dB of the full export in librlottie",
                   t.tolerance_1024, t.residual_scale, t.worst_db);
      outcome.lottie_measured = true;
      outcome.lottie_tolerance_1024 = choice->tolerance_1024;
      outcome.lottie_residual_scale = choice->residual_scale;
      outcome.lottie_db = choice->worst_db;
      lottie.compact = choice->worst_db >= kCompactTargetDb + kCompactMarginDb;
      lottie.decimals = lottie.compact ? settings.decimals : kDefaultDecimals;
      lottie.tolerance_px = choice->tolerance_1024 * px_per_1024;
      lottie.residual_scale = choice->residual_scale;
    } else if (outcome.tolerance_db != 0) {
      // No player to measure it: a fixed step tighter than animation.svg's (tolerance_choice.h),
      // its residual shapes no looser than animation.svg's transform tolerance: the residual scale
      // is measured on our render of animation.svg and does not carry over to librlottie (the
      // bundled man: animation.svg held 46.8 dB at 6 x, animation.json fell to 43.7 dB at 6 x and
      // 44.7 at 3 x of its own tighter tolerance, 45.9 at 2 x).
      lottie.tolerance_px = lottie_tolerance(outcome.tolerance_1024) * px_per_1024;
      lottie.residual_scale = std::min(outcome.residual_scale, outcome.tolerance_1024 / lottie.tolerance_px * px_per_1024);
    }
    lottie.dotlottie = fs::path(anim).replace_extension(".lottie");
    for (const std::string& w : write_lottie(json, doc.scene, plan, written.points, wt, lottie, map))
      outcome.warnings.push_back(w);
  }
  return outcome;
}

ExportOutcome export_fit_directory(const fs::path& dir, const fs::path& out, const ExportSettings& settings, bool lock) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(dir.string() + ": not a folder");
  if (!fs::is_directory(dir / ".svgmotion", ec)) throw Error(dir.string() + ": not a svgmotion run or fit directory");
  const fs::path ckpt = dir / "checkpoint.bin";
  if (!fs::exists(ckpt, ec)) throw Error(ckpt.string() + ": no checkpoint (no fit has run in " + dir.string() + ")");
  FitResult result = load_fit_result(ckpt);
  // Paths the fit kept relative to its folder (its own copies in a run directory).
  for (std::string* p : {&result.svg, &result.export_into})
    if (!p->empty() && fs::path(*p).is_relative()) *p = (dir / *p).string();
  if (!fs::exists(result.svg, ec)) throw Error(result.svg + ": the fitted SVG is gone (" + ckpt.string() + " needs it)");
  const Scene as_read = read_svg_file(result.svg);
  const SplitPlan split = plan_segment_split(as_read, result.max_segment * std::max(as_read.width, as_read.height));
  const Scene fitted = split_scene(as_read, split);
  const ExportDocument doc = export_document(as_read, split, result.svg, result.export_into);
  // The control-point layout only: a tiny plan.
  const RasterPlan plan = plan_raster(fitted, Affine{}, 8, 8);
  if (plan.n_cp != result.n_cp)
    throw Error(result.svg + ": changed since the fit (" + std::to_string(plan.n_cp) + " control points, the fit has " +
                std::to_string(result.n_cp) + "); fit it again");
  std::optional<RunLock> held;
  if (lock) held.emplace(out, false, fit_output_names());
  return write_animation_files(result, settings, doc, plan,
                               out / (result.rejected ? "animation.failed.svg" : "animation.svg"));
}

}  // namespace svgm
