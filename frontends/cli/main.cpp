// The svgmotion command-line tool: dispatches subcommands and turns every error into one line.
//
// Errors (svgm::Error and anything else) print "svgmotion: <message>" on stderr and exit 1;
// usage mistakes exit 2; a result that must not be trusted (svgm::Rejected) exits 3 or 4.
// `svgmotion CMD --help` prints the command's options. Nothing is written by a command that fails (outputs are atomic).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "cli/malloc_policy.h"
#include "pipeline/batch.h"
#include "report/rerun_command.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace {

constexpr const char* kUsage = R"(svgmotion )" SVGM_VERSION R"(: an editable animated SVG from a static SVG and a motion

usage:
  svgmotion run [X.svg ["PROMPT"]] [CONFIG.yaml|fast|paper] [--input X.svg] [--prompt "..."]
                [-o RUN_DIR] [--from STAGE]
                [--device D] [--quiet] [key.path=value ...]
  svgmotion fit IN.svg --target VIDEO|FRAMES_DIR -o OUT_DIR [options]
  svgmotion render IN.svg -o OUT.png [--size W] [--background white|transparent] [--time T]
                   [--device D] [--strict]
  svgmotion render ANIMATION.svg -o CLIP.mp4|.webm|.gif|.webp|DIR/%04d.png [--fps F] [--size W]
                   [--quality CRF] [--background white|transparent]
  svgmotion batch MANIFEST -o OUT_DIR [CONFIG.yaml] [--shard I/N] [--device D] [--pin]
                  [key.path=value ...]
  svgmotion report RUN_DIR [--device D]
  svgmotion config [--show CONFIG] [key.path=value ...]
  svgmotion export RUN_DIR|FIT_DIR [-o OUT_DIR] [--precision N] [--inbetweens N]
                   [--format svg,lottie,gif,mp4,webm,webp] [--full]
                   [--fps F] [--quality CRF] [--transparent]
  svgmotion plugins
  svgmotion devices [--warm]
  svgmotion palette N
  svgmotion bench render|raster IN.svg [--frames K] [--size N] [--repeat R] [--json] [--profile]
                   [--device D]
  svgmotion bench raster IN.svg [IN2.svg ...] [options]
  svgmotion bench raster --scaling [--json]
  svgmotion bench fit IN.svg --target VIDEO [--iterations N] [--keyframes K] [--size N] [--json]
  svgmotion bench target VIDEO [--size N] [--keyframes K] [--denoise R] [--stabilise] [--repeat R]
                   [--json]
  svgmotion help | --version | CMD --help

--device picks the OpenCL device: auto (default), cpu, gpu, or part of its name.
Every command takes --verbose (-v: debug lines too) and --quiet (-q: warnings and errors
only; twice: errors only). `run` also appends every line, debug included, to RUN_DIR/log.txt.
Exit status: 0 done, 1 error (one line says what), 2 usage, 3 the fit was rejected by the
result gate (animation.failed.svg written instead of animation.svg), 4 every candidate video
was flagged by the ranker (run stopped before fitting), 130 interrupted.
)";

struct CommandHelp {
  const char* name;
  const char* text;
};

constexpr CommandHelp kHelp[] = {
    {"run", R"(usage: svgmotion run [X.svg ["PROMPT"]] [CONFIG.yaml] [options] [key.path=value ...]

The whole pipeline in a run directory: grouper, recolorer, video, ranker, layers, tracker,
fitter, each a plugin named in the config (`svgmotion config` lists every key). Stages whose
plugin, settings and inputs are unchanged are skipped. Every setting is checked before the
first stage runs. The run directory keeps the merged config (resolved.yaml) and log.txt the
command line, quoted for sh.

  X.svg "PROMPT"     the SVG to animate and the motion in words (as --input, --prompt); a
                     file is an SVG by its .svg extension or its content (it starts with '<')
  CONFIG.yaml        a config merged over the defaults (configs/default.yaml); a built-in
                     one by name from any folder: fast, paper (fast.yaml, paper.yaml)
  --input X.svg      the SVG to animate (config key: input)
  --prompt TEXT      the motion in words (prompt)
  -o, --output DIR   the run directory (output; default: run)
  --from STAGE       run STAGE and everything after it even if up to date
  --force            use DIR even if it is a non-empty folder that is not a run directory
                     (the run writes beside your files, never over one)
  --device D         OpenCL device: auto, cpu, gpu or part of a name (device)
  --quiet            no progress on stderr
  key.path=value     any setting, e.g. stages.fitter.iterations=500 stages.video.plugin=file

Writes animation.svg (your own document, only `d` animated), animation.json (Lottie),
preview.mp4, fit.json and every intermediate. Exit status 3: the fit was rejected (animation.failed.svg, reasons in fit.json);
4: every candidate video was flagged (set stages.ranker.accept_flagged=true to fit anyway);
130: interrupted by Ctrl-C, SIGTERM or SIGHUP (run again to continue).
)"},
    {"fit", R"(usage: svgmotion fit IN.svg --target VIDEO|FRAMES_DIR -o OUT_DIR [options]

Fits the SVG's paths to a target video (mp4, webm, avi, mov, or a folder of numbered PNGs).

  --target SOURCE        the target video or folder of PNG frames (required)
  -o, --output DIR       where animation.svg, animation.json (Lottie), preview.mp4, fit.json,
                         checkpoint.bin go (required)
  --iterations N         optimiser iterations (default 2000)
  --keyframes K          keyframes sampled from the target (default 15)
  --size N               fitting width in pixels (default 256; 32..4096)
  --palette P.json       the colour each path id has in the target (from the recolorer)
  --mask-threshold T     foreground when the darkest channel is below T (default 0.97)
  --loop MODE            loop (default; seamless when the target returns to its start),
                         once, or mirror
  --deform D             field (default: a smooth displacement field per part, so thin parts
                         hold together at any size) or free (the paper's per-point offsets)
  --precision P          decimal places of the exported coordinates (default: the fewest that
                         keep the compact export's tolerance; 0..6)
  --full                 write every value of every path (the per-frame export) instead of the
                         compact one (only what moves, fewest keyframes, affine motion as a
                         transform on a new <g> around the element)
  --inbetweens N         smooth in-between shapes per keyframe interval (default 3; 0..16;
                         0 leaves them to the player's straight lines: smallest files)
  --group-transforms     each part's motion, where affine, as <animateTransform> elements
                         (translate, rotate, skewX, scale) and its paths' shapes in its frame
  --max-segment F        split (exactly) every path segment longer than F of the canvas's
                         larger side before fitting, so the motion can bend it (default
                         0.04; 0: keep the paths' own segments)
  --refine-size W|auto|0 after the fit, refine every keyframe at width W for an eighth more
                         iterations (default auto: twice the fitting width when the video
                         has at least 1.5x it; 0: off)
  --stabilise            remove camera shake (the whole frame jittering) from the video first
                         (default: when the video is measured to shake; --no-stabilise: never)
  --denoise R            average each sampled frame with its R neighbours on either side, moved
                         onto it by optical flow, against codec noise (default 2; 0..4; 0: off)
  --no-colour-correction compare with the video's colours as they are (default: each frame's
                         colours are corrected towards the palette, absorbing drift and shading)
  --no-blur-matching     blur the drawing in the loss as the paper does, even when the video is
                         softer (default: the video's blur, measured on its first frame against
                         the drawing at rest, is matched)
  --chroma-weight auto|W how much an error of colour alone (chroma) counts in the loss against
                         one of brightness (luma), in (0, 1]; codecs keep chroma at a quarter
                         of the resolution and quantise it harder (default auto: 1 unless the
                         first frame's chroma is visibly softer than its luma; then the weight
                         of 1, 0.5, 0.25 under which a short fit of the first frame, the drawing
                         at rest, drifts least from rest; 1 unless another is clearly better)
  --no-gate              write animation.svg even when the result gate rejects the fit
  --resume               continue from OUT_DIR/checkpoint.bin
  --no-track             no optical-flow warm start of new keyframes
  --force                use OUT_DIR even if it is a non-empty folder that is not a run
                         directory (written beside your files, never over one)
  --all-iterations       run every iteration (default: the fit ends once every keyframe is
                         active and the loss has stopped falling; fit.json converged_at)
  --device D             OpenCL device
  --quiet                no progress line

Exit status 3 when the result gate rejects the fit (animation.failed.svg is written instead of
animation.svg; fit.json has the reasons); 130 after Ctrl-C (the result so far is written).
)"},
    {"render", R"(usage: svgmotion render IN.svg -o OUT.png [options]
       svgmotion render ANIMATION.svg -o CLIP.mp4|.webm|.gif|.webp|DIR/%04d.png [options]

Renders the SVG (an animated one at --time T) to a PNG, or one pass of its SMIL animation to a
clip: an mp4 (H.264, BT.709-tagged, index first so it streams), a WebM (VP9, with alpha under
--background transparent), a GIF (FFmpeg's palettegen/paletteuse colours, only the changed
rectangle per frame; binary alpha under --background transparent), or numbered PNG frames
(frame i at i/F seconds), or an animated WebP (lossless; transparent under --background
transparent). The format follows OUT's extension, and OUT may not be the input.

  -o, --output OUT         the image or clip to write (required)
  --fps F                  clip frame rate (default: the animation's own, data-svgmotion-fps
                           on its root as svgmotion writes it; else 30)
  --size W                 width in pixels (default: the SVG's own; height by its aspect)
  --background B           white (default) or transparent (PNG, GIF, WebM, WebP; not mp4)
  --quality CRF            mp4/webm constant quality, lower is better: H.264 0..51 (default 20),
                           VP9 0..63 (default 31)
  --time T                 seconds into the SMIL animation
  --edges E                browser (default: strokes outlined and edges rounded to quarter
                           pixels in y as Chromium draws them) or exact (exact area coverage,
                           what the fitter sees)
  --device D               OpenCL device
  --strict                 unsupported content is an error, not a warning
)"},
    {"batch", R"(usage: svgmotion batch MANIFEST -o OUT_DIR [CONFIG.yaml] [options] [key.path=value ...]

Runs `svgmotion run` for every item of MANIFEST (CSV with a header row, or YAML) in
OUT_DIR/<id>/, one process per item, so a failing item never stops the others. Finished items
are up to date on a re-run (the runs' manifests), failed and interrupted ones resume. Each
item's record is OUT_DIR/<id>/batch.json; when the shard ends (and at most once a minute while
it runs) OUT_DIR/summary.csv and summary.json list every item: status (done, failed,
rejected, flagged, interrupted, pending), reason, seconds, fidelity (worst keyframe PSNR and
IoU), peak memory.

  MANIFEST           columns/keys: input (required), id, prompt, target (a video: fitted to it
                     through the file provider), overrides ("key.path=value ...": settings,
                     not options); paths relative to it
  -o, --output DIR   where the run directories and the summary go (required)
  CONFIG.yaml        a config for every item; key.path=value settings follow (items' last)
  --shard I/N        take items I, I+N, I+2N, ... (counted from 0); under a Slurm job array
                     the array variables pick the shard
  --device D         OpenCL device for every item
  --pin              pin PoCL's threads to cores (only for a batch alone on its machine)
  --summary          only write the summary from the items' records (no item runs)
  --quiet            no line per item

Threads follow SLURM_CPUS_PER_TASK and the CPUs this process may use. Exit status 0 when
every item of the shard is done, 1 when some are not (see the summary), 2 for a bad Slurm
array variable, 130 interrupted.
)"},
    {"report", "usage: svgmotion report RUN_DIR [--device D]\n\nWrites RUN_DIR/report.html: the run's self-contained preview page (the animation with play/pause\nand a scrubber, the input, every candidate video with the ranker's scores and the command that\nfits another one, the target beside the fit, the losses, the stage timings). `run` writes it\nat the end of every run.\n"},
    {"config", R"(usage: svgmotion config [--show CONFIG] [key.path=value ...]

Lists every config key with its default, its type and its meaning (from configs/default.yaml,
built in). With --show, prints the config CONFIG (a file, or a built-in one by name: default,
fast, paper) merged over the defaults with the overrides after it, as YAML that `run` takes;
each setting that is not a default says where it came from.
)"},
    {"export", R"(usage: svgmotion export RUN_DIR|FIT_DIR [options]

Writes a finished fit's animation again from DIR/checkpoint.bin, without fitting: change the
precision, the in-betweens or compact/full, or make clips, in a second instead of a refit.

  -o, --output DIR     where to write (default: DIR itself; another folder becomes a run directory)
  --precision N        decimal places of the coordinates (default: the fewest that keep the
                       compact tolerance; 0..6)
  --inbetweens N       smooth in-between shapes per keyframe interval (default 3; 0..16)
  --format LIST        comma-separated: svg, lottie (animation.json), gif, mp4, webm, webp (clips are
                       rendered from animation.svg, which is written with them); default svg,lottie
  --full               every value of every path (the per-frame export)
  --tolerance P        the compact export's tolerance in pixels at 1024 px (default: measured,
                       the largest of 0.25..3 whose render keeps 46 dB of the full export)
  --fps F              clip frame rate (default: the fit's, the target video's)
  --quality CRF        mp4/webm quality, lower is better (render --help)
  --transparent        gif, webm and webp clips without the white background (mp4 stays on white)
)"},
    {"plugins", "usage: svgmotion plugins\n\nLists the stage plugins found (stage, name, version, path) and every\nrefused module with its reason.\n"},
    {"devices", "usage: svgmotion devices [--warm [--device D]]\n\nLists the OpenCL devices; * marks the one --device auto picks.\n"
                "  --warm     compiles every kernel program a default run uses for the device and caches it\n"
                "             (a first run otherwise spends most of a minute compiling)\n"},
    {"palette", "usage: svgmotion palette N\n\nPrints N maximally distinct colours (white reserved), one #rrggbb per line.\n"},
    {"bench", R"(usage: svgmotion bench render|raster IN.svg [options]
       svgmotion bench raster IN.svg [IN2.svg ...] [options]
       svgmotion bench raster --scaling [--json]
       svgmotion bench fit IN.svg --target VIDEO [options]
       svgmotion bench target VIDEO [options]

  render        median time per frame of K frames rendered in one batch
  raster        one differentiable iteration (forward, loss, backward) over K frames, against
                librsvg's render of them; several SVGs are timed one after the other
  fit           a whole fit at fit's defaults, without its outputs: setup, iterations, CPU time
  target        loading a target as fit does (decode, denoise, --stabilise), median of R loads
  --frames K    frames per batch (default 15)
  --size N      width in pixels (default 256)
  --repeat R    repetitions (the median is reported)
  --keyframes K keyframes sampled (fit, target; default 15)
  --iterations N  the fit's iteration budget (fit)
  --target VIDEO  the video the fit follows (fit)
  --denoise R   temporal denoising radius (target; default 2, as fit)
  --stabilise   remove camera shake too (target)
  --json        one JSON object per scene (ms_per_frame / forward_ms, backward_ms, total_ms, peak_rss_mb, device;
                target: wall_s, cpu_s, denoise_s, shake_model, max_shake_px, peak_rss_mb)
  --profile     per-kernel times
  --scaling     sweep paths, size and frames on procedural scenes (raster)
  --device D    OpenCL device
)"},
};

const char* command_help(const std::string& cmd) {
  for (const CommandHelp& h : kHelp)
    if (cmd == h.name) return h.text;
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  svgm::cli::use_returning_malloc();  // freed frames go back to the system (malloc_policy.h)
  svgm::follow_batch_parent();  // an item of `svgmotion batch` ends with its batch
  // Bad input must give our one error line, not FFmpeg's or OpenCV's chatter before it. These
  // are read when OpenCV first loads its video back end, i.e. after this point.
  setenv("OPENCV_LOG_LEVEL", "SILENT", 0);
  setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);  // AV_LOG_QUIET
  std::vector<std::string> args(argv + 1, argv + argc);
  // The global levels (svgmotion/log.h) before the command; after it, the command's own parser
  // takes them (cli_args.h), so that an option's value is never taken for one (`--prompt -q`).
  {
    // Quoted for sh, so log.txt's command line can be pasted back as it was typed.
    std::string line = "svgmotion";
    for (int i = 1; i < argc; ++i) line += " " + svgm::shell_quote(argv[i]);
    svgm::log::set_command_line(line);
    int quiet = 0, verbose = 0;
    size_t lead = 0;
    while (lead < args.size() && svgm::cli::is_log_flag(args[lead], quiet, verbose)) ++lead;
    args.erase(args.begin(), args.begin() + static_cast<long>(lead));
    try {
      svgm::cli::add_log_flags(quiet, verbose);
    } catch (const svgm::Error& e) {
      std::fprintf(stderr, "svgmotion: %s\n", e.what());
      return 2;
    }
  }
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || (args[0] == "help" && args.size() == 1)) {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version" || args[0] == "version") {
    std::printf("svgmotion %s\n", SVGM_VERSION);
    return 0;
  }
  if (args[0] == "help") {  // svgmotion help CMD
    if (const char* h = command_help(args[1])) return std::fputs(h, stdout), 0;
    std::fprintf(stderr, "svgmotion: unknown command '%s' (try svgmotion help)\n", args[1].c_str());
    return 2;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      if (const char* h = command_help(cmd)) return std::fputs(h, stdout), 0;
      break;
    }
  try {
    if (cmd == "render") return svgm::cli::cmd_render(args);
    if (cmd == "devices") return svgm::cli::cmd_devices(args);
    if (cmd == "bench") return svgm::cli::cmd_bench(args);
    if (cmd == "fit") return svgm::cli::cmd_fit(args);
    if (cmd == "palette") return svgm::cli::cmd_palette(args);
    if (cmd == "run") return svgm::cli::cmd_run(args);
    if (cmd == "plugins") return svgm::cli::cmd_plugins(args);
    if (cmd == "batch") return svgm::cli::cmd_batch(args);
    if (cmd == "report") return svgm::cli::cmd_report(args);
    if (cmd == "config") return svgm::cli::cmd_config(args);
    if (cmd == "export") return svgm::cli::cmd_export(args);
    std::fprintf(stderr, "svgmotion: unknown command '%s' (try svgmotion help)\n", cmd.c_str());
    return 2;
  } catch (const svgm::Rejected& e) {
    svgm::log::error("%s", e.what());
    return e.exit_status();
  } catch (const svgm::cli::UsageError& e) {
    svgm::log::error("%s", e.what());
    return 2;
  } catch (const svgm::Error& e) {
    svgm::log::error("%s", e.what());
    return 1;
  } catch (const std::exception& e) {
    svgm::log::error("internal error: %s", e.what());
    return 1;
  }
}
