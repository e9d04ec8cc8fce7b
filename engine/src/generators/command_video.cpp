#include "generators/command_video.h"

#include <cmath>
#include <cstdio>

#include "svgmotion/error.h"
#include "svgmotion/target_video.h"
#include "plugin/plugin_options.h"
#include "generators/command_runner.h"
#include "svgmotion/utf8_text.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& message) { throw Error("video command: " + message); }

std::string two_digits(int i) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", i);
  return buf;
}

}  // namespace

CommandVideoOptions parse_command_video_options(const nlohmann::json& options) {
  const PluginOptions opt(options, "video command",
                          {"argv", "candidates", "frames", "timeout_s", "fps", "prompt_template"});
  CommandVideoOptions o;
  o.candidates = opt.whole("candidates", o.candidates, 1, 99);
  o.frames = opt.whole("frames", o.frames, 1, 100000);
  o.timeout_s = opt.number("timeout_s", o.timeout_s);
  if (o.timeout_s <= 0) opt.fail("options.timeout_s must be > 0 seconds");
  o.fps = opt.number("fps", o.fps);
  if (o.fps <= 0 || o.fps > 1000) opt.fail("options.fps must be in (0, 1000]");
  o.prompt_template = opt.string("prompt_template", o.prompt_template);
  if (opt.has("argv")) {
    const auto& a = opt.at("argv");
    if (!a.is_array()) fail("options.argv must be a list of strings, not " + json_text(a));
    for (const auto& e : a) {
      if (e.is_string()) o.argv.push_back(e.get<std::string>());
      else if (e.is_number()) o.argv.push_back(json_text(e));
      else fail("options.argv elements must be strings, not " + json_text(e));
    }
  }
  if (o.argv.empty())
    fail("options.argv is not set (the generator's command line, e.g. [python3, gen.py, "
         "--image, \"{image}\", --out, \"{out}\"])");
  if (o.argv[0].empty()) fail("options.argv[0] is empty (the program to run)");
  bool has_out = false;
  for (const auto& a : o.argv) has_out = has_out || a.find("{out}") != std::string::npos;
  if (!has_out) fail("options.argv never mentions {out} (where the generator writes its video)");
  return o;
}

std::vector<fs::path> generate_candidates(const CommandVideoOptions& options,
                                          const fs::path& run_dir_in, const std::string& prompt,
                                          int64_t seed, const CommandVideoHooks& hooks) {
  if (options.argv.empty() || options.argv[0].empty()) fail("options.argv is not set");
  const fs::path run_dir = fs::absolute(run_dir_in).lexically_normal();
  const fs::path image = run_dir / "recolored.png";
  const fs::path svg = run_dir / "recolored.svg";
  if (!fs::is_regular_file(image)) fail(image.string() + ": no such file (the recoloured image)");

  // The whole argv is checked before anything runs or is deleted: a typo in a placeholder
  // costs nothing.
  std::string full_prompt = replace_placeholder(options.prompt_template, "prompt", prompt);
  while (!full_prompt.empty() && (full_prompt.back() == ' ' || full_prompt.back() == '\n'))
    full_prompt.pop_back();  // an empty prompt leaves no trailing space
  auto values_for = [&](int i) {
    return std::map<std::string, std::string>{
        {"image", image.string()},
        {"svg", svg.string()},
        {"prompt", full_prompt},
        {"seed", std::to_string(seed + i)},
        {"index", std::to_string(i)},
        {"frames", std::to_string(options.frames)},
        {"fps", short_number(options.fps)},
        {"out", (run_dir / "candidates" / (two_digits(i) + ".mp4")).string()},
        {"run_dir", run_dir.string()},
    };
  };
  try {
    (void)expand_argv(options.argv, values_for(0));
  } catch (const Error& e) {
    fail(std::string("options.argv: ") + e.what());
  }

  const fs::path dir = run_dir / "candidates";
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (ec) fail(dir.string() + ": cannot empty: " + ec.message());
  fs::create_directories(dir, ec);
  if (ec) fail(dir.string() + ": cannot create: " + ec.message());

  std::vector<fs::path> outputs;
  const int n = options.candidates;
  for (int i = 0; i < n; ++i) {
    const std::string nn = two_digits(i);
    const std::string label = "candidate " + nn + ": ";
    if (hooks.cancelled && hooks.cancelled()) fail(label + "cancelled before it started");
    if (hooks.progress)
      hooks.progress(static_cast<double>(i) / n, "candidate " + std::to_string(i + 1) + " of " +
                                                    std::to_string(n));
    const auto values = values_for(i);
    const std::vector<std::string> argv = expand_argv(options.argv, values);
    const fs::path out = values.at("out");
    const fs::path log = dir / (nn + ".log");
    const std::string log_rel = "candidates/" + nn + ".log";
    if (hooks.log) hooks.log("video command: " + label + "running " + argv[0] + " (seed " +
                             values.at("seed") + ", log " + log_rel + ")");

    const CommandResult r = run_command(argv, log, options.timeout_s, hooks.cancelled);
    if (!r.ok())
      fail(label + argv[0] + " " + describe(r, options.timeout_s) + " (see " + log_rel + ")");

    const std::string out_rel = "candidates/" + nn + ".mp4";
    std::string why;
    if (!fs::exists(out)) {
      why = "no such file";
    } else {
      try {
        const TargetInfo info = probe_target(out);
        if (info.frames < 1) why = "it has no frames";
        else if (hooks.log)
          hooks.log("video command: " + label + out_rel + ": " + std::to_string(info.frames) +
                    " frames of " + std::to_string(info.width) + "x" +
                    std::to_string(info.height) + " at " + short_number(info.fps) + " fps in " +
                    short_number(std::round(r.seconds * 10) / 10) + " s");
      } catch (const Error& e) {
        why = e.what();
        const std::string prefix = out.string() + ": ";
        if (why.rfind(prefix, 0) == 0) why = why.substr(prefix.size());
      }
    }
    if (!why.empty())
      fail(label + argv[0] + " wrote no readable video at " + out_rel + ": " + why);
    outputs.push_back(out);
  }
  if (hooks.progress) hooks.progress(1.0, "done");
  return outputs;
}

}  // namespace svgm
