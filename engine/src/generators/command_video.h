// The video stage's `command` plugin, minus the plugin boundary: runs an external image-to-video
// generator once per candidate from an argv template (no shell), each writing
// candidates/NN.mp4 in the run directory, and checks that every output is a readable video.
#pragma once

#include "generators/generator_hooks.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace svgm {

// The paper's wording around the user's motion prompt.
inline constexpr const char* kDefaultVideoPromptTemplate =
    "A flat 2D vector illustration in the same style, solid colours, no 3D, no shading changes, "
    "keep every shape and colour exactly, plain white background. {prompt}";

struct CommandVideoOptions {
  // The generator's argv; placeholders {image} {svg} {prompt} {seed} {frames} {fps} {out}
  // {index} {run_dir} (see generate_candidates). Must mention {out}.
  std::vector<std::string> argv;
  int candidates = 4;    // 1..99
  int frames = 49;       // passed to the generator as {frames}
  double timeout_s = 600;  // per candidate
  double fps = 24;         // passed to the generator as {fps}
  std::string prompt_template = kDefaultVideoPromptTemplate;  // "{prompt}" = the user's prompt
};

// Reads request["config"]["options"] (null or missing = all defaults except argv, which is
// required). Integers may come as whole numbers of any JSON type; argv elements may be strings
// or numbers (YAML turns an unquoted 24 into a number). Throws svgm::Error "video command:
// options.<key> ..." for a wrong type or range, an unknown key (naming the known ones), a
// missing or empty argv, or an argv without {out}.
CommandVideoOptions parse_command_video_options(const nlohmann::json& options);

using CommandVideoHooks = GeneratorHooks;

// Runs the generator for candidates 0..N-1 in order, in `run_dir` (absolute or not; made
// absolute here): candidates/ is emptied first, then for candidate i ("NN" = i, two digits)
// argv is expanded with
//   {image}   absolute run_dir/recolored.png      {svg}    absolute run_dir/recolored.svg
//   {prompt}  options.prompt_template with {prompt} = `prompt`
//   {seed}    seed + i                             {index}  i
//   {frames}  options.frames                       {fps}    options.fps ("24", "23.976")
//   {out}     absolute run_dir/candidates/NN.mp4   {run_dir} absolute run_dir
// and run with its output in candidates/NN.log. Returns the candidate files. Throws svgm::Error
// with one line on the first failure, leaving candidates/ as it is:
//   "video command: candidate 00: <argv0> exited with status 3 (see candidates/00.log)"
//   "video command: candidate 00: <argv0> timed out after 5 s (see candidates/00.log)"
//   "video command: candidate 00: <argv0> wrote no readable video at candidates/00.mp4: <why>"
// (also "... was killed by signal N (...)", "... could not be started: <why>", "... was
// cancelled"). Nothing outside candidates/ is written.
std::vector<std::filesystem::path> generate_candidates(const CommandVideoOptions& options,
                                                       const std::filesystem::path& run_dir,
                                                       const std::string& prompt, int64_t seed,
                                                       const CommandVideoHooks& hooks = {});

}  // namespace svgm
