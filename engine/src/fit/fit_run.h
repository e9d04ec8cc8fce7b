// The steps of one fit job (fit_job.h) and what each hands the next: run_fit_job() is the list
// of steps, in order; a FitRun holds the fit's state between them (inputs, the target, the
// fitters, the report). Internal to fit/: fit_job.cpp (reading and preparing),
// fit_stages.cpp (the coarse fit, keyframes from the target, the refinement) and
// fit_outputs.cpp (the animation files, fit.json, the closing message).
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "export/group_transform.h"
#include "export/smil_writer.h"
#include "fit/fit_job.h"
#include "fit/fit_progress.h"
#include "fit/optimise/fitter.h"
#include "fit/output/animation_export.h"
#include "fit/output/result_gate.h"
#include "fit/plan/motion_groups.h"
#include "fit/plan/segment_split.h"
#include "fit/target/blur_match.h"
#include "fit/target/chroma_calibration.h"
#include "fit/target/compact_raw.h"
#include "fit/target/frame_scan.h"
#include "fit/target/rest_start.h"
#include "fit/target/white_runs.h"
#include "opencl/runtime.h"
#include "run/run_directory.h"
#include "svgmotion/render_size.h"
#include "svgmotion/scene.h"
#include "svgmotion/target_video.h"

namespace svgm {

// The refinement's guard: a keyframe whose refined fit matches the video this many times worse
// at the coarse width than its coarse fit did keeps the coarse fit. Refined keyframes that are
// fine score 0.98-1.17 times the coarse loss there (the coarse loss does not reward detail
// finer than its pixels); a small shape the refinement lost scores 21-24 times (snail).
constexpr float kRefineGuard = 1.5f;
// The joint fit after keyframes were added from the target: at most this share of the
// iteration budget (it usually ends earlier, at the plateau test).
constexpr double kKeyedShare = 0.25;
constexpr int kCheckpointEvery = 250;  // iterations between checkpoints
// The loss is sampled for fit.json's loss_history every this many iterations: 200 samples for
// the default 2000 iterations, a few kB of JSON, enough for the report's chart.
constexpr int kLossHistoryEvery = 10;

// printf of up to four numbers, for messages and fit.json keys.
std::string fit_fmt(const char* f, double a, double b = 0, double c = 0, double d = 0);
// Does the target end where it began? (the loop is closed when it does)
bool returns_to_start(const TargetFrames& t);

struct FitRun {
  FitRun(const FitJob& job, const std::function<bool()>& interrupted);

  // The steps, in the order run_fit_job() takes them.
  void read_drawing();          // the SVG, its segment split, palette and motion groups
  void prepare_target();        // the target's keyframes, colour correction, the rest start
  void claim_output();          // the output folder, refused now rather than after the fit
  void plan_stages();           // coarse and refinement widths, budgets and blur matching
  void choose_chroma_weight();  // the job's, or calibrated on the first frame
  void start_fitter();          // the coarse fitter, its tracks, a checkpoint to resume
  void fit_coarse();            // the coarse stage, checkpointed
  void add_keyframes_from_target();  // frames the spline misses become keyframes
  void refine();                // every keyframe at the finer width, with its guard
  void write_animation();       // the result gate, animation.svg/.json, preview.mp4
  void write_report();          // fit.json
  int finish();                 // the closing message and the exit status

  // Helpers of the steps.
  void release_denoised();
  // The OpenCL compiler's clean pages out of the resident set (opencl/compiler_pages.h), once
  // the programs of the step named `after` are built; logged with the MB dropped.
  void release_compiler_pages(const char* after);
  double work(int it) const;
  // `done`: a match already made at this width (the rest start's, prepare_target).
  BlurMatch match_blur(const TargetFrames& t, const RenderSize& at, const BlurMatch* done = nullptr);
  void prepare_fine();
  void run_stage(Fitter& f, int done_before, bool checkpoints);
  // Seconds since the job began (the progress estimate's clock).
  double seconds_in() const;
  // Tells the host's bar what the fit is doing now (a step with no iterations of its own: the
  // bar would otherwise stand still for tens of seconds without a word; issue 37).
  void activity(const std::string& note);
  // The frames the keyframe choice will judge from `poses` (every frame of the target, or the
  // poses a lower frame rate shows) and its keyframe budget; `poses` empty when it will not run.
  void choice_plan(std::vector<int>& poses, int& budget) const;

  const FitJob& job;
  const std::function<bool()>& interrupted;
  const std::filesystem::path& input;
  const std::filesystem::path& out;
  const FitOptions& fo;
  const int keyframes;
  const std::string target_str;
  const std::string* target_path;
  const std::chrono::steady_clock::time_point begun = std::chrono::steady_clock::now();

  // read_drawing
  Scene as_read;
  SplitPlan split;
  Scene scene;
  std::vector<std::string> held_groups;
  KnownMotion known;
  Scene fit_scene;
  // prepare_target
  RenderSize size;
  TargetOptions to;
  std::optional<ClRuntime> rt;
  double gradient_share = 0;
  std::filesystem::path into;
  std::optional<Scene> export_scene;
  ExportMap map;
  TargetFrames target;
  FrameScan scan;  // the target's held frames and shake, read before sampling (frame_scan.h)
  BlurMatch first_blur;  // blur matching at the fitting width, before the rest start is judged
  RestStart rest_start;
  bool pin_rest = false;
  // The keyframes chosen from the target, when frames were added (keyframe_choice.h).
  std::optional<TargetFrames> keyed_target;
  // claim_output
  std::optional<RunLock> lock;
  // plan_stages
  int refine_w = 0;
  int refine_iters = 0;
  FitOptions coarse_options;
  // The coarse stage's iterations: the budget, or fewer when its loss stops falling
  // (FitOptions::plateau_window; set when the stage ends).
  int coarse_iters = 0;
  int total_iters = 0;
  double fine_cost = 1;
  double total_work = 0;
  BlurMatch coarse_blur;
  // The refinement's target and options (its chroma weight is set below), made on first use:
  // before the coarse fit when the chroma weight's calibration mirrors the refinement too.
  std::optional<TargetFrames> fine_target;
  // Its rgba packed as runs of white (fit/target/white_runs.h) while nothing reads it: from the
  // chroma weight's calibration to the finer fitter's start, and from before its Q and R are
  // made to the refinement's end (88 MB of floats for 21 keyframes at 512 px).
  WhiteRuns fine_rgba;
  bool fine_packed = false;
  void pack_fine_rgba();
  void unpack_fine_rgba();
  void drop_fine_target();
  BlurMatch fine_blur;
  FitOptions fine_options;
  // The coarse stage's target: the first load, or the keyframes chosen from the target.
  const TargetFrames* coarse_target = nullptr;
  // choose_chroma_weight
  double chroma_weight = 1;
  std::optional<ChromaCalibration> chroma_cal;
  std::optional<ChromaGate> chroma_gate;
  // start_fitter
  std::optional<Fitter> fitter;
  std::filesystem::path ckpt;
  std::string key;
  // fit_coarse and the stages after it
  int resumed_from = 0;
  bool tty = false;
  std::chrono::steady_clock::time_point t0, last_print;
  LossTerms loss;
  bool stopped = false;
  // Divergence watch: the best per-keyframe loss since the last activation, a snapshot of the
  // last good state (taken every kSnapshotEvery iterations while the loss is sane).
  int bad_streak = 0;
  float best = 0;
  int best_active = 0, rollbacks = 0;
  FitState good;  // taken at the start of each stage
  std::vector<std::string> rollback_notes;
  // fit.json's loss_history (report.html charts it): iteration, total loss, image loss and
  // active keyframes, every kLossHistoryEvery iterations and at the end of each stage.
  struct LossSample {
    int iteration;
    float total, image;
    int active;
  };
  std::vector<LossSample> history;
  std::optional<FitProgress> bar;
  FitState coarse_state;
  bool coarse_converged = false;
  // add_keyframes_from_target
  nlohmann::json key_report;
  std::unique_ptr<Fitter> keyed;
  // refine
  std::unique_ptr<Fitter> fine;
  std::vector<int> refine_kept_coarse;  // keyframes the refinement's guard put back
  std::vector<float> refine_loss_ratio;  // per keyframe: refined / coarse loss at the coarse width
  // write_animation
  int iterations_done = 0;
  RenderSize final_size;
  double seconds = 0;
  AnimationTiming timing;
  GateOptions gate_options;
  GateVerdict verdict;
  bool rejected = false;
  std::filesystem::path anim;
  std::optional<GroupMotionExport> group_motion;
  int values_written = 0;

  // The targets' frames before cleanup, compacted once each is loaded (fit/target/compact_raw.h:
  // only the preview and the gate read them after the load): `target`'s, `keyed_target`'s and
  // `fine_target`'s.
  CompactRaw target_raw, keyed_raw, fine_raw;

  Fitter& coarse_fit() { return keyed ? *keyed : *fitter; }
  Fitter& final_fit() { return fine ? *fine : coarse_fit(); }
  const TargetFrames& final_target() const { return fine ? *fine_target : *coarse_target; }
  // The gate's reader of the final target's cleaned frames: a keyframe at a time from the runs
  // when the finer target's are packed (they stay so after the refinement); none (the gate
  // reads final_target().rgba) otherwise.
  CleanedFrameReader final_cleaned_reader() const;
  const CompactRaw& final_raw() const { return fine ? fine_raw : coarse_target == &target ? target_raw : keyed_raw; }
};

}  // namespace svgm
