// `svgmotion batch`: many drawings, one run directory each, resumable, shardable over a job
// array.
//
// Each item of the shard runs as its own `svgmotion run` process (started with posix_spawn, no
// shell: video/command_runner.h) in OUT/<id>/, its output in OUT/<id>/batch.log. A process per
// item isolates items: a crash, an OpenCL driver fault or a leak in one drawing ends that
// item only, and the item's peak memory is the process's own (wait4). The run's stage
// manifests make a batch idempotent: a finished item is up to date and costs a few seconds, a
// failed or interrupted one resumes from where it stopped.
//
// After every item its record goes to OUT/<id>/batch.json, and the summary of the whole
// manifest (all shards: items without a record are "pending") is rewritten to
// OUT/summary.csv and OUT/summary.json under an advisory lock (OUT/.summary.lock), so shards
// finishing at once never lose each other's rows. Statuses: done, failed (exit 1 or a crash:
// the reason is the run's error line), rejected (the result gate; exit 3), flagged (every
// candidate video; exit 4), interrupted, pending.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/batch_manifest.h"
#include "pipeline/batch_shard.h"

namespace svgm {

struct BatchOptions {
  std::filesystem::path out_dir;
  std::filesystem::path program;                // the svgmotion binary run per item
  std::optional<std::filesystem::path> config;  // a config file passed to every run
  std::vector<std::string> overrides;           // key.path=value for every run (items' come after)
  std::optional<std::string> device;            // --device for every run
  Shard shard;
  std::function<bool()> cancelled;              // polled while an item runs (Ctrl-C, scancel)
  std::function<void(const std::string&)> say;  // one line per item started and finished
};

struct BatchItemResult {
  std::string id, status, reason;
  double seconds = 0;
  std::optional<double> psnr_db, iou;  // the fit's worst keyframe (fit.json's gate), when fitted
  double peak_rss_mb = 0;
  int exit_status = -1;
};

struct BatchOutcome {
  int items = 0;  // in this shard
  int done = 0, not_done = 0;
  bool interrupted = false;
};

// Runs the items of `options.shard`, in manifest order. Throws svgm::Error only when OUT
// cannot be created; every problem of an item is in its record.
BatchOutcome run_batch(const std::vector<BatchItem>& items, const BatchOptions& options);

// The `svgmotion run` arguments for one item (after the program name).
std::vector<std::string> batch_run_argv(const BatchItem& item, const BatchOptions& options);

// Rewrites OUT/summary.csv and OUT/summary.json from the records of every item of the
// manifest, under the summary lock; returns the rows written.
std::vector<BatchItemResult> write_batch_summary(const std::vector<BatchItem>& items,
                                                 const std::filesystem::path& out_dir);

}  // namespace svgm
