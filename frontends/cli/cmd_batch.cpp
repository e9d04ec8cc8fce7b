// `svgmotion batch`: every drawing of a manifest, one run directory each (pipeline/batch.h),
// this process's shard of them when several run side by side (a Slurm job array, or --shard).
//
// Items run as child `svgmotion run` processes of this same binary. Their PoCL workers are not
// pinned to cores unless --pin asks (SVGMOTION_PIN in their environment): shards sharing a
// machine would otherwise pin to the same cores (opencl/cpu_share.h). Ctrl-C or SIGTERM (what
// scancel sends) stops the running item, records it as interrupted, and ends with status 130.
// A Slurm array variable that is not a whole number in range is a usage error (status 2).
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "pipeline/batch.h"
#include "svgmotion/error.h"
#include "svgmotion/log.h"

namespace svgm::cli {

namespace fs = std::filesystem;

namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_batch_signal(int) { g_stop = 1; }

}  // namespace

int cmd_batch(const std::vector<std::string>& argv) {
  const Args a = parse_args("batch", argv, {"-o", "--output", "--shard", "--device"}, {"--pin", "--summary"});
  std::optional<fs::path> manifest, config;
  std::vector<std::string> overrides;
  for (const std::string& p : a.positional) {
    if (p.find('=') != std::string::npos) overrides.push_back(p);
    else if (!manifest) manifest = p;
    else if (!config) config = fs::absolute(p);
    else throw UsageError("batch: unexpected argument '" + p + "' (MANIFEST, one config file, then key.path=value)");
  }
  if (!manifest) throw UsageError("batch: no manifest (usage: svgmotion batch MANIFEST -o OUT_DIR)");
  const auto out = a.get("-o") ? a.get("-o") : a.get("--output");
  if (!out) throw UsageError("batch: -o OUT_DIR is required");
  if (config && !fs::is_regular_file(*config)) throw Error(config->string() + ": cannot open: No such file");
  for (const std::string& ov : overrides) check_batch_override(ov);

  BatchOptions o;
  const std::vector<BatchItem> items = read_batch_manifest(*manifest);
  o.out_dir = fs::absolute(*out);
  if (a.has("--summary")) {  // on demand, from the records: no item runs
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    if (ec) throw Error(o.out_dir.string() + ": cannot create: " + ec.message());
    const std::vector<BatchItemResult> rows = write_batch_summary(items, o.out_dir);
    int done = 0;
    for (const BatchItemResult& r : rows) done += r.status == "done";
    std::printf("batch: %d of %zu items done; summary in %s\n", done, rows.size(),
                (o.out_dir / "summary.csv").c_str());
    return 0;
  }
  o.config = config;
  o.overrides = overrides;
  if (const auto d = a.get("--device")) o.device = *d;
  if (const auto s = a.get("--shard")) {
    o.shard = parse_shard(*s);
  } else {
    try {
      if (const auto s = shard_from_slurm([](const char* n) { return std::getenv(n); })) o.shard = *s;
    } catch (const Error& e) {
      log::error("%s", e.what());
      return 2;
    }
  }
  std::error_code ec;
  o.program = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("batch: cannot find the svgmotion binary (/proc/self/exe): " + ec.message());
  setenv("SVGMOTION_PIN", a.has("--pin") ? "1" : "0", 0);  // for the items' runs; the user's wins
  mark_batch_parent();  // the items' runs end with this process, even on SIGKILL

  const bool quiet = log::quiet();
  o.say = [quiet](const std::string& line) {
    if (!quiet) std::printf("batch: %s\n", line.c_str()), std::fflush(stdout);
  };
  g_stop = 0;
  o.cancelled = [] { return g_stop != 0; };
  std::signal(SIGINT, on_batch_signal);
  std::signal(SIGTERM, on_batch_signal);
  o.say("shard " + o.shard.name() + " of " + manifest->string() + " into " + o.out_dir.string());
  const BatchOutcome r = run_batch(items, o);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);

  const std::string where = (o.out_dir / "summary.csv").string();
  if (r.interrupted) {
    log::error("batch interrupted; %d of %d items of shard %s done (see %s; run again to resume)",
                 r.done, r.items, o.shard.name().c_str(), where.c_str());
    return 130;
  }
  if (r.not_done > 0) {
    log::error("batch: %d of %d items of shard %s not done (see %s)", r.not_done, r.items,
                 o.shard.name().c_str(), where.c_str());
    return 1;
  }
  std::printf("batch: shard %s: %d of %d items done; summary in %s\n", o.shard.name().c_str(), r.done, r.items,
              where.c_str());
  return 0;
}

}  // namespace svgm::cli
