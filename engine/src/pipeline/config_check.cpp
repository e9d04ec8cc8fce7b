// Checking a run's settings up front (see config_check.h).
#include "pipeline/config_check.h"
#include "pipeline/candidate_choice.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "color/palette.h"
#include "svg/utf8.h"
#include "svgmotion/device.h"
#include "svgmotion/error.h"
#include "svgmotion/svg_reader.h"
#include "svgmotion/target_video.h"
#include "procedural/prompt_parse.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

const nlohmann::json& at(const nlohmann::json& c, const std::string& path) {
  static const nlohmann::json null;
  const nlohmann::json* j = &c;
  size_t from = 0;
  while (from <= path.size()) {
    const size_t dot = path.find('.', from);
    const std::string key = path.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
    if (!j->is_object() || !j->contains(key)) return null;
    j = &(*j)[key];
    if (dot == std::string::npos) break;
    from = dot + 1;
  }
  return *j;
}

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::string shown(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : json_text(v); }

void whole(const nlohmann::json& c, const std::string& key, long long lo, long long hi) {
  const nlohmann::json& v = at(c, key);
  if (v.is_null()) return;
  const bool ok = v.is_number_integer() ? v.get<long long>() >= lo && v.get<long long>() <= hi
                  : v.is_number_float() ? std::isfinite(v.get<double>()) && v.get<double>() == std::floor(v.get<double>()) &&
                                              v.get<double>() >= static_cast<double>(lo) && v.get<double>() <= static_cast<double>(hi)
                                        : false;
  if (!ok)
    throw Error(key + ": must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                ", not " + shown(v));
}

void real(const nlohmann::json& c, const std::string& key, double lo, double hi, bool open_lo) {
  const nlohmann::json& v = at(c, key);
  if (v.is_null()) return;
  const double x = v.is_number() ? v.get<double>() : NAN;
  if (!(std::isfinite(x) && (open_lo ? x > lo : x >= lo) && x <= hi))
    throw Error(key + ": must be a number in " + (open_lo ? "(" : "[") + number(lo) + ", " + number(hi) +
                "], not " + shown(v));
}

void one_of(const nlohmann::json& c, const std::string& key, std::initializer_list<const char*> allowed) {
  const nlohmann::json& v = at(c, key);
  if (v.is_null()) return;
  std::string list;
  for (const char* a : allowed) {
    if (v.is_string() && v.get<std::string>() == a) return;
    list += (list.empty() ? "" : ", ") + std::string(a);
  }
  throw Error(key + ": must be one of " + list + ", not " + shown(v));
}

}  // namespace

void check_config(const nlohmann::json& c, const PluginHost& host) {
  // Plugins first: a misspelt plugin is the commonest mistake and names the others.
  for (const std::string& stage : stage_names()) {
    const std::string key = "stages." + stage + ".plugin";
    const nlohmann::json& v = at(c, key);
    if (!v.is_string() || v.get<std::string>().empty()) throw Error(key + ": must name a " + stage + " plugin");
    if (!host.find(stage, v.get<std::string>())) {
      std::string have;
      for (const PluginInfo& p : host.plugins())
        if (p.stage == stage) have += (have.empty() ? "" : ", ") + p.name;
      std::string why;
      for (const std::string& pr : host.problems())
        if (pr.find("svgm_" + stage + "_" + v.get<std::string>()) != std::string::npos) why = " (" + pr + ")";
      throw Error(key + ": no " + stage + " plugin '" + v.get<std::string>() + "'" + why + "; available: " +
                  (have.empty() ? "none" : have));
    }
  }
  whole(c, "seed", 0, 4294967295LL);
  whole(c, "stages.grouper.max_groups", 1, 256);
  whole(c, "stages.video.candidates", 1, 64);
  whole(c, "stages.video.frames", 2, 10000);
  real(c, "stages.video.fps", 0, 1000, true);
  whole(c, "stages.video.size", 32, 4096);
  if (const nlohmann::json& r = at(c, "stages.video.room"); !(r.is_string() && r.get<std::string>() == "auto")) {
    const double x = r.is_number() ? r.get<double>() : NAN;
    if (!(x >= 0 && x <= 0.5)) throw Error("stages.video.room: must be auto or a share from 0 to 0.5, not " + shown(r));
  }
  whole(c, "stages.tracker.grid", 2, 512);
  whole(c, "stages.fitter.iterations", 1, 1000000);
  whole(c, "stages.fitter.keyframes", 2, 1000);
  whole(c, "stages.fitter.size", 32, 4096);
  if (const nlohmann::json& m = at(c, "stages.fitter.max_keyframes"); !m.is_null() && !(m.is_string() && m.get<std::string>() == "auto"))
    if (!m.is_number_integer() || m.get<long long>() < 0 || m.get<long long>() > 10000)
      throw Error("stages.fitter.max_keyframes: must be auto or a whole number from 0 to 10000, not " + shown(m));
  one_of(c, "stages.fitter.start", {"auto", "rest", "free"});
  if (const nlohmann::json& r = at(c, "stages.fitter.refine_size"); !r.is_null() && !(r.is_string() && r.get<std::string>() == "auto"))
    if (!r.is_number_integer() || r.get<long long>() < 0 || r.get<long long>() > 4096)
      throw Error("stages.fitter.refine_size: must be auto or a whole number from 0 to 4096, not " + shown(r));
  check_candidate_choice(at(c, "stages.ranker.choose"));
  real(c, "stages.fitter.mask_threshold", 0, 1, true);
  one_of(c, "stages.fitter.colors", {"auto", "palette", "original"});
  one_of(c, "stages.fitter.loop", {"loop", "once", "mirror"});
  one_of(c, "stages.fitter.deform", {"field", "free"});
  if (const nlohmann::json& p = at(c, "stages.fitter.precision"); !p.is_null() && !(p.is_string() && p.get<std::string>() == "auto"))
    whole(c, "stages.fitter.precision", 0, 6);  // kMaxDecimals (smil_writer.h)
  whole(c, "stages.fitter.inbetweens", 0, 16);  // kMaxInbetweens (fit_job.h)
  real(c, "stages.fitter.max_segment", 0, 1, false);
  whole(c, "stages.fitter.denoise", 0, 4);  // kMaxDenoiseRadius (fit_job.h)
  if (const nlohmann::json& w = at(c, "stages.fitter.chroma_weight"); !w.is_null() && !(w.is_string() && w.get<std::string>() == "auto")) {
    const double x = w.is_number() ? w.get<double>() : NAN;
    if (!(std::isfinite(x) && x > 0 && x <= 1))
      throw Error("stages.fitter.chroma_weight: must be auto or a number in (0, 1], not " + shown(w));
  }
  if (at(c, "stages.video.plugin") == "procedural" && at(c, "stages.fitter.keyframes").is_number() &&
      at(c, "stages.video.frames").is_number() &&
      at(c, "stages.fitter.keyframes").get<double>() > at(c, "stages.video.frames").get<double>())
    throw Error("stages.fitter.keyframes: " + shown(at(c, "stages.fitter.keyframes")) +
                " keyframes need at least as many video frames (stages.video.frames is " +
                shown(at(c, "stages.video.frames")) + ")");

  // The procedural video's explicit motion plan: its grammar (verbs, modifiers) is checked now;
  // its part patterns only once the parts exist.
  if (at(c, "stages.video.plugin") == "procedural") {
    const nlohmann::json& opts = at(c, "stages.video.options");
    if (opts.is_object() && opts.contains("motion")) {
      if (!opts["motion"].is_string()) throw Error("stages.video.options.motion: must be a string like \"flap:wing*, bob:whole\"");
      try {
        parse_explicit_plan(opts["motion"].get<std::string>());
      } catch (const Error& e) {
        throw Error(std::string("stages.video.options.motion: ") + e.what());
      }
    }
  }

  const nlohmann::json& prompt = at(c, "prompt");
  if (prompt.is_string() && !valid_utf8(prompt.get<std::string>()))
    throw Error("prompt: is not valid UTF-8 text");
  const nlohmann::json& device = at(c, "device");
  if (!device.is_string()) throw Error("device: must be auto, cpu, gpu or part of a device name");
  try {
    select_device(list_devices(), device.get<std::string>());
  } catch (const Error& e) {
    throw Error(std::string("device: ") + e.what());
  }

  const std::string input = at(c, "input").is_string() ? at(c, "input").get<std::string>() : "";
  if (input.empty()) throw Error("input: no input SVG (set input: in the config or pass --input)");
  std::error_code ec;
  if (!fs::exists(input, ec)) throw Error(input + ": cannot open: No such file or directory");
  if (fs::is_directory(input, ec)) throw Error(input + ": is a folder, not an SVG file");
  if (!fs::is_regular_file(input, ec)) throw Error(input + ": not a regular file");
  if (::access(input.c_str(), R_OK) != 0) throw Error(input + ": cannot open: Permission denied");
  {
    const Scene s = read_svg_file(input);  // throws "<input>: <problem>" for malformed SVG
    if (s.paths.empty()) throw Error(input + ": nothing to animate (no visible paths)");
    // The recolorer gives every path its own colour; known now, so the error names the
    // user's file instead of the run directory's grouped.svg after the grouper has run.
    if (at(c, "stages.recolorer.plugin") == "spherepack" && s.paths.size() > static_cast<size_t>(kMaxPaletteSize))
      throw Error(input + ": " + std::to_string(s.paths.size()) + " paths, more than the " +
                  std::to_string(kMaxPaletteSize) + " distinct colours the spherepack recolorer makes "
                  "(stages.recolorer.plugin=none keeps the drawing's own colours)");
  }
  if (at(c, "stages.video.plugin") == "file") {
    const std::string path = at(c, "stages.video.path").is_string() ? at(c, "stages.video.path").get<std::string>() : "";
    if (path.empty()) throw Error("stages.video.path: video: file needs the video (or folder of PNG frames) to fit");
    if (!fs::exists(path, ec)) throw Error(path + ": cannot open: No such file or directory");
    // Opened (and its frames counted) now, so a broken or too short video fails in one line
    // naming the user's file, not at the video or tracker stage after grouping and recolouring
    // have filled the run directory (or naming the run directory's copy, target.mp4).
    const TargetInfo info = probe_target(path);  // throws "<path>: <problem>"
    const auto keyframes = at(c, "stages.fitter.keyframes");
    if (keyframes.is_number() && info.frames < keyframes.get<double>())
      throw Error(path + ": has " + std::to_string(info.frames) + (info.frames == 1 ? " frame" : " frames") +
                  ", fewer than the " + shown(keyframes) + " keyframes asked for (stages.fitter.keyframes)");
  }
  const std::string output = at(c, "output").is_string() ? at(c, "output").get<std::string>() : "";
  if (output.empty()) throw Error("output: must name the run directory");
  if (fs::exists(output, ec) && !fs::is_directory(output, ec))
    throw Error(output + ": exists and is not a folder (the run directory)");
  fs::path probe = fs::absolute(output, ec);
  while (!probe.empty() && !fs::exists(probe, ec)) probe = probe.parent_path();
  // Named by the folder that cannot be written (the run directory or the nearest existing
  // folder above it), with the reason.
  if (!probe.empty() && ::access(probe.c_str(), W_OK | X_OK) != 0)
    throw Error(probe.string() + ": cannot write (" + (errno == EROFS ? "read-only file system" : "permission denied") + ")");
}

}  // namespace svgm
