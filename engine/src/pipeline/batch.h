// `svgmotion batch`: many drawings, one run directory each, resumable, shardable over a job
// array.
//
// Each item of the shard runs as its own `svgmotion run` process (started with posix_spawn, no
// shell: generators/command_runner.h) in OUT/<id>/, its output in OUT/<id>/batch.log. A process per
// item isolates items: a crash, an OpenCL driver fault or a leak in one drawing ends that
// item only, and the item's peak memory is the process's own (wait4). The run's stage
// manifests make a batch idempotent: a finished item is up to date and costs a few seconds, a
// failed or interrupted one resumes from where it stopped.
//
// After every item its record goes to OUT/<id>/batch.json (one small file: an item costs the
// same in a manifest of 10 or 100,000). The summary of the whole manifest (all shards: items
// without a record are "pending"), OUT/summary.csv and OUT/summary.json, is assembled from the
// records when the shard ends, while it runs at most once a minute (and at most a twentieth of
// its time), and on demand (`batch --summary`); numbered assemblies (write_batch_summary) keep
// shards finishing at once from replacing a newer summary with an older one. Statuses: done,
// failed (exit 1 or a crash: the reason is the run's error line), rejected (the result gate;
// exit 3), flagged (every candidate video; exit 4), interrupted, pending.
//
// One batch per shard and output folder at a time (OUT/.shard-I-of-N.lock, holding its pid). An
// item's run dies with its batch (follow_batch_parent), and a run still working in an item's
// directory (an earlier batch's, which outlived it) is waited for, not reported as a failure.
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
// cannot be created or another batch is running the same shard into it ("OUT: shard 0/2 is
// already running into this folder (batch pid 123)"); every problem of an item is in its
// record.
BatchOutcome run_batch(const std::vector<BatchItem>& items, const BatchOptions& options);

// The `svgmotion run` arguments for one item (after the program name).
std::vector<std::string> batch_run_argv(const BatchItem& item, const BatchOptions& options);

// Assembles OUT/summary.csv and OUT/summary.json from the records of every item of the
// manifest; returns the rows. The files are replaced unless a summary whose assembly started
// later (another shard's) has been written meanwhile.
std::vector<BatchItemResult> write_batch_summary(const std::vector<BatchItem>& items,
                                                 const std::filesystem::path& out_dir);

// The batch side and the item side of "an item's run dies with its batch": the batch puts its
// pid in the environment its items inherit (SVGMOTION_BATCH_PARENT); the item's process, first
// thing, asks the kernel for SIGTERM when that parent dies (prctl PR_SET_PDEATHSIG: a batch
// killed with SIGKILL left its item's run working on as an orphan), ends at once if the parent
// is already gone, and removes the variable so its own children do not inherit it.
// posix_spawn runs no code of ours in the child, hence the variable.
void mark_batch_parent();
void follow_batch_parent();

}  // namespace svgm
