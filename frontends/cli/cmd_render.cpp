// `svgmotion render`: rasterise an SVG to a PNG through the OpenCL renderer, or an animated SVG
// to a clip (mp4, webm, gif or a numbered PNG sequence) of its whole animation.
//
// The output format follows the extension (export/clip_writer.h); any other is refused before
// anything is read, and the output may never be the input file itself (the same file under
// another name or through a link included). A clip's frame at time T is exactly what
// `render --time T` draws (raster/render_image.h), so frames and stills agree.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "export/clip_writer.h"
#include "export/smil_clock.h"
#include "media/video_encoder.h"
#include "opencl/runtime.h"
#include "raster/render_image.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"
#include "svgmotion/png_io.h"
#include "svgmotion/svg_reader.h"

namespace svgm::cli {

namespace {

// A common video rate, for an animation that does not state its own (data-svgmotion-fps, which
// svgmotion's writer adds: a fitted animation's clip is at the fit's rate).
constexpr double kDefaultFps = 30;
constexpr double kMaxFps = 240;       // beyond any display
constexpr int kMaxClipFrames = 100000;  // about an hour at 30 fps: a mistake, not a clip

}  // namespace

int cmd_render(const std::vector<std::string>& argv) {
  const Args a = parse_args("render", argv,
                            {"-o", "--output", "--size", "--background", "--device", "--time", "--fps", "--quality",
                             "--edges"},
                            {"--strict"});
  if (a.positional.size() != 1)
    throw UsageError("render: expected one input SVG (svgmotion render IN.svg -o OUT.png)");
  const std::string input = a.positional[0];
  const auto out = a.get("-o") ? a.get("-o") : a.get("--output");
  if (!out || out->empty()) throw UsageError("render: missing -o OUT.png");
  std::error_code ec;
  if (std::filesystem::equivalent(input, *out, ec))
    throw Error(*out + ": is the input file; choose another output name");
  const ClipFormat format = clip_format(*out);
  const bool still = format == ClipFormat::Still;
  const std::string bg = a.get("--background").value_or("white");
  if (bg != "white" && bg != "transparent")
    throw Error("render: --background must be white or transparent, got '" + bg + "'");
  const bool transparent = bg == "transparent";
  const int width = a.get_int("--size", 0, 1, 16384);
  // Browser edges by default: strokes outlined as Chromium outlines them (quadratic offsets cut
  // into few chords, raster/browser_stroke.h; hairlines for strokes at most a pixel wide) and
  // edge end points rounded to quarter pixels in y as its rasteriser does
  // (RasterPlan::browser_edges). Stills and clips are for people, who compare them with what a
  // browser shows: strokes then match Chromium's to 38-57 dB instead of 34-43
  // (tests/tools/stroke_agreement.py). `exact` draws what the fitter sees (exact area coverage).
  const std::string edges = a.get("--edges").value_or("browser");
  if (edges != "exact" && edges != "browser")
    throw Error("render: --edges must be exact or browser, got '" + edges + "'");
  const bool browser_edges = edges == "browser";
  if (!still && a.has("--time"))
    throw Error("render: --time is for a still image; a clip (" + *out + ") shows the whole animation");
  if (still && a.has("--fps")) throw Error("render: --fps is for clips (.mp4, .webm, .gif, .webp, frames/%04d.png)");
  double fps = a.get_double("--fps", kDefaultFps);
  if (!(fps >= 1 && fps <= kMaxFps)) throw Error("render: --fps wants a frame rate in [1, 240]");
  if (transparent && format == ClipFormat::Mp4)
    throw Error("render: --background transparent needs PNG, GIF, WebM or WebP output; mp4 (H.264) has no alpha");
  ClipOptions clip_options;
  clip_options.transparent = transparent;
  if (a.has("--quality")) {
    if (format != ClipFormat::Mp4 && format != ClipFormat::Webm)
      throw Error("render: --quality is for mp4 and webm clips (a CRF, lower is better)");
    const int max = format == ClipFormat::Mp4 ? kMaxH264Crf : kMaxVp9Crf;
    clip_options.quality = a.get_int("--quality", -1, 0, max);
  }

  SvgReadLimits read_options;
  read_options.animation_time = a.get_double("--time", -1);
  if (a.has("--time") && !(read_options.animation_time >= 0))
    throw Error("render: --time wants a number of seconds >= 0");
  Scene scene = read_svg_file(input, read_options);
  for (const auto& w : scene.warnings) log::warning("%s", w.c_str());
  if (a.has("--strict") && !scene.warnings.empty())
    throw Error(input + ": warnings are errors under --strict");

  if (still) {
    ClRuntime rt(a.get("--device").value_or("auto"));
    const RgbaImage img = render_image(rt, scene, width, transparent, browser_edges);
    write_png(*out, img);
    log::info("svgmotion: wrote %s (%dx%d)", out->c_str(), img.width, img.height);
    return 0;
  }

  // A clip: one pass of the animation (a loop's frame at the full duration is its first, so it
  // is left out and the clip loops cleanly; an animation that plays once ends on its last pose).
  std::ifstream in(input, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const SmilClock clock = smil_clock(text, input);
  if (clock.animations == 0)
    throw Error(input + ": no SMIL animation (<animate> with a dur) to make a clip of; render a still with -o OUT.png");
  // A clip is at the animation's own frame rate (the fit's, stated by our writer) unless asked.
  if (!a.has("--fps") && clock.fps > 0) fps = clock.fps;
  ClRuntime rt(a.get("--device").value_or("auto"));
  const double exact = clock.duration_s * fps;
  if (!(exact < kMaxClipFrames)) throw Error(input + ": the animation is too long for a clip at this frame rate");
  const int frames = std::max(1, static_cast<int>(std::lround(exact))) + (clock.repeats ? 0 : 1);
  int w = 0, h = 0;
  write_clip(*out, format, frames, fps, clock.repeats, [&](int i) {
    SvgReadLimits at;
    at.animation_time = i / fps;
    const RgbaImage img = render_image(rt, read_svg_string(text, input, at), width, transparent, browser_edges);
    w = img.width;
    h = img.height;
    return img;
  }, clip_options);
  log::info("svgmotion: wrote %s (%d frames at %g fps, %.3g s, %dx%d%s)", out->c_str(), frames, fps,
               frames / fps, w, h, clock.repeats ? ", loops" : "");
  return 0;
}

}  // namespace svgm::cli
