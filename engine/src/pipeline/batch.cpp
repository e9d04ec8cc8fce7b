// Running a batch of items, one `svgmotion run` process each (see batch.h).
#include "pipeline/batch.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <thread>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "generators/command_runner.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRecord = "batch.json";  // an item's record, in its run directory
constexpr const char* kLog = "batch.log";      // the item's `svgmotion run` output
constexpr const char* kParentVariable = "SVGMOTION_BATCH_PARENT";  // see follow_batch_parent()

// The summary is assembled from every item's record, O(items) in files read: a 100,000-item
// manifest took 2-5 s, which after every item made that the batch's cost. While items run it
// is refreshed at most this often, and at most a twentieth of the time (20x the last assembly),
// besides once at the end of the shard.
constexpr std::chrono::seconds kSummaryEvery{60};
constexpr int kSummaryTimeShare = 20;

// How often a re-run looks whether an earlier run still holding an item's run directory has
// ended (and whether it was cancelled meanwhile).
constexpr std::chrono::milliseconds kWaitPoll{200};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The run's own one-line error ("svgmotion: <message>", the last such line that is not a
// warning), or nothing.
std::string error_line(const std::string& log) {
  std::istringstream in(log);
  std::string last;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("svgmotion: ", 0) == 0 && line.rfind("svgmotion: warning:", 0) != 0) last = line.substr(11);
  return last;
}

std::optional<double> worst(const nlohmann::json& a) {
  if (!a.is_array() || a.empty()) return std::nullopt;
  double w = INFINITY;
  for (const auto& v : a)
    if (v.is_number()) w = std::min(w, v.get<double>());
  return std::isfinite(w) ? std::optional<double>(w) : std::nullopt;
}

nlohmann::json to_json(const BatchItemResult& r) {
  nlohmann::json j = {{"id", r.id},         {"status", r.status},           {"reason", r.reason},
                      {"seconds", r.seconds}, {"peak_rss_mb", r.peak_rss_mb}, {"exit_status", r.exit_status}};
  j["fidelity_psnr_db"] = r.psnr_db ? nlohmann::json(*r.psnr_db) : nlohmann::json(nullptr);
  j["fidelity_iou"] = r.iou ? nlohmann::json(*r.iou) : nlohmann::json(nullptr);
  return j;
}

// JSON text of a record or summary. Reasons quote the run's error line and inputs are paths,
// either of which may hold bytes that are not UTF-8 (a Latin-1 file name), which nlohmann
// refuses to write (type_error 316, an "internal error" that ended the batch): those bytes
// become U+FFFD. (The shared bytes-to-UTF-8 function of the non-UTF-8 names work may replace
// this once it lands.)
std::string dump(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::optional<BatchItemResult> read_record(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("status")) return std::nullopt;
  BatchItemResult r;
  r.id = j.value("id", "");
  r.status = j.value("status", "");
  r.reason = j.value("reason", "");
  r.seconds = j.value("seconds", 0.0);
  r.peak_rss_mb = j.value("peak_rss_mb", 0.0);
  r.exit_status = j.value("exit_status", -1);
  if (j.contains("fidelity_psnr_db") && j["fidelity_psnr_db"].is_number()) r.psnr_db = j["fidelity_psnr_db"].get<double>();
  if (j.contains("fidelity_iou") && j["fidelity_iou"].is_number()) r.iou = j["fidelity_iou"].get<double>();
  return r;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string number(std::optional<double> v, int decimals) {
  if (!v) return "";
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, *v);
  return b;
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return b;
}

std::string host_name() {
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) != 0) return "?";
  return host;
}

// An exclusive advisory lock on a file, released on destruction (or by the kernel when the
// process dies). Non-blocking, `held()` says whether it was had; the file holds a little text
// (a pid, the summary's tickets) read and replaced under the lock.
class FileLock {
 public:
  explicit FileLock(const fs::path& file, bool wait = true) {
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw Error(file.string() + ": cannot open the lock: " + std::strerror(errno));
    while (::flock(fd_, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0) {
      if (errno == EWOULDBLOCK && !wait) return;
      if (errno != EINTR) {
        ::close(fd_);
        throw Error(file.string() + ": cannot lock: " + std::strerror(errno));
      }
    }
    held_ = true;
  }
  ~FileLock() { ::close(fd_); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;
  bool held() const { return held_; }
  std::string text() const {
    char b[64] = {0};
    const ssize_t n = ::pread(fd_, b, sizeof b - 1, 0);
    return n > 0 ? std::string(b, static_cast<size_t>(n)) : std::string();
  }
  void set_text(const std::string& t) const {
    if (::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, t.data(), t.size(), 0) < 0) {}
  }

 private:
  int fd_ = -1;
  bool held_ = false;
};

// The pid in a lock file's text, for messages ("" when there is none).
std::string pid_in(const std::string& text) {
  const size_t end = text.find_first_not_of("0123456789");
  return text.substr(0, end);
}

// An `svgmotion run` still working in the item's run directory holds its lock (RunLock in
// pipeline.cpp: .svgmotion/lock, flock, its pid inside): an item run that outlived its batch
// (one killed with SIGKILL before follow_batch_parent() existed, or another batch's). Starting
// our own run now would only fail ("another svgmotion run is using this run directory") and
// record the item failed while that run finishes it; waiting lets ours find it up to date.
// Returns false when cancelled while waiting.
bool wait_for_earlier_run(const fs::path& dir, const std::function<bool()>& cancelled,
                          const std::function<void(const std::string&)>& say) {
  const int fd = ::open((dir / ".svgmotion" / "lock").c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return true;  // never run
  bool said = false, ok = true;
  for (;;) {
    if (::flock(fd, LOCK_SH | LOCK_NB) == 0) break;
    if (errno == EINTR) continue;
    if (errno != EWOULDBLOCK) break;  // cannot tell: let the run itself decide
    if (!said && say) {
      char b[32] = {0};
      const ssize_t n = ::pread(fd, b, sizeof b - 1, 0);
      const std::string pid = pid_in(n > 0 ? std::string(b, static_cast<size_t>(n)) : "");
      say("waiting for svgmotion run" + (pid.empty() ? std::string() : " pid " + pid) +
          ", still working in " + dir.string() + " (an earlier batch's?)");
      said = true;
    }
    if (cancelled && cancelled()) {
      ok = false;
      break;
    }
    std::this_thread::sleep_for(kWaitPoll);
  }
  ::close(fd);  // releases our shared lock before our own run takes it exclusively
  return ok;
}

// What one finished `svgmotion run` means for the item.
BatchItemResult judge(const BatchItem& item, const CommandResult& r, const fs::path& dir,
                      const std::optional<BatchItemResult>& before) {
  BatchItemResult res;
  res.id = item.id;
  res.seconds = r.seconds;
  res.peak_rss_mb = static_cast<double>(r.peak_rss_kb) / 1024.0;
  res.exit_status = r.spawn_error.empty() && !r.signalled ? r.status : -1;
  const std::string log = read_text(dir / kLog);
  const std::string err = error_line(log);
  if (r.ok()) {
    res.status = "done";
    // Every stage up to date: nothing was fitted now; keep the time and memory of the run
    // that did the work.
    if (log.find("every stage is up to date") != std::string::npos) {
      res.reason = "up to date";
      if (before && before->status == "done") {
        res.seconds = before->seconds;
        res.peak_rss_mb = before->peak_rss_mb;
      }
    }
  } else if (r.cancelled || res.exit_status == 130) {
    res.status = "interrupted";
    res.reason = "stopped; run the batch again to resume";
  } else if (res.exit_status == Rejected::kFitRejected) {
    res.status = "rejected";
  } else if (res.exit_status == Rejected::kCandidatesFlagged) {
    res.status = "flagged";
  } else {
    res.status = "failed";
  }
  if (res.status != "done" && res.status != "interrupted")
    res.reason = !err.empty() && !r.signalled ? err : "svgmotion run " + describe(r, 0);
  if (res.status == "done" || res.status == "rejected") {
    std::ifstream in(dir / "fit.json");
    const nlohmann::json fit = nlohmann::json::parse(in, nullptr, false);
    if (fit.is_object() && fit.contains("gate") && fit["gate"].is_object()) {
      res.psnr_db = worst(fit["gate"].value("keyframe_psnr_db", nlohmann::json()));
      res.iou = worst(fit["gate"].value("keyframe_iou", nlohmann::json()));
    }
  }
  return res;
}

}  // namespace

std::vector<std::string> batch_run_argv(const BatchItem& item, const BatchOptions& o) {
  std::vector<std::string> a = {"run"};
  if (o.config) a.push_back(o.config->string());
  a.insert(a.end(), {"--input", item.input.string(), "--prompt", item.prompt, "-o",
                     (o.out_dir / item.id).string(), "--quiet"});
  if (o.device) a.insert(a.end(), {"--device", *o.device});
  if (!item.target.empty()) {
    a.push_back("stages.video.plugin=file");
    a.push_back("stages.video.path=" + item.target.string());
  }
  a.insert(a.end(), o.overrides.begin(), o.overrides.end());
  a.insert(a.end(), item.overrides.begin(), item.overrides.end());
  return a;
}

// Summaries are numbered (tickets, in OUT/.summary.lock: "NEXT WRITTEN") when their assembly
// starts, and one replaces the files only when none started later has been written: a shard
// that began reading the records before another shard's last item finished must not overwrite
// that shard's newer summary. The records are read without the lock, so shards finishing at
// once read side by side; the lock covers only taking a ticket and the rename.
std::vector<BatchItemResult> write_batch_summary(const std::vector<BatchItem>& items, const fs::path& out) {
  const fs::path lock_file = out / ".summary.lock";
  unsigned long long ticket = 0;
  {
    const FileLock lock(lock_file);
    unsigned long long next = 0, written = 0;
    std::sscanf(lock.text().c_str(), "%llu %llu", &next, &written);
    ticket = next + 1;
    lock.set_text(std::to_string(ticket) + " " + std::to_string(written) + "\n");
  }
  std::vector<BatchItemResult> rows;
  std::map<std::string, int> counts;
  nlohmann::json jrows = nlohmann::json::array();
  std::string csv = "id,status,reason,seconds,fidelity_psnr_db,fidelity_iou,peak_rss_mb\n";
  for (const BatchItem& item : items) {
    BatchItemResult r = read_record(out / item.id / kRecord).value_or(BatchItemResult{});
    r.id = item.id;
    if (r.status.empty()) r.status = "pending";
    ++counts[r.status];
    jrows.push_back(to_json(r));
    csv += csv_field(r.id) + "," + r.status + "," + csv_field(r.reason) + "," +
           (r.status == "pending" ? "" : number(r.seconds, 1)) + "," + number(r.psnr_db, 2) + "," +
           number(r.iou, 3) + "," + (r.status == "pending" ? "" : number(r.peak_rss_mb, 0)) + "\n";
    rows.push_back(std::move(r));
  }
  const nlohmann::json summary = {{"items", jrows}, {"counts", counts}, {"total", items.size()}, {"updated", utc_now()}};
  const std::string json = dump(summary);
  const FileLock lock(lock_file);
  unsigned long long next = 0, written = 0;
  std::sscanf(lock.text().c_str(), "%llu %llu", &next, &written);
  if (ticket > written) {
    write_file_atomic(out / "summary.csv", csv);
    write_file_atomic(out / "summary.json", json);
    lock.set_text(std::to_string(std::max(next, ticket)) + " " + std::to_string(ticket) + "\n");
  }
  return rows;
}

BatchOutcome run_batch(const std::vector<BatchItem>& items, const BatchOptions& o) {
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  if (ec) throw Error(o.out_dir.string() + ": cannot create: " + ec.message());
  // One batch per shard and output folder: a second one would start the same items, find
  // them locked by the first one's runs and record them failed while the first finishes them.
  const FileLock shard_lock(o.out_dir / (".shard-" + std::to_string(o.shard.index) + "-of-" +
                                         std::to_string(o.shard.count) + ".lock"),
                            false);
  if (!shard_lock.held()) {
    const std::string pid = pid_in(shard_lock.text());
    throw Error(o.out_dir.string() + ": shard " + o.shard.name() + " is already running into this folder" +
                (pid.empty() ? std::string() : " (batch pid " + pid + ")"));
  }
  shard_lock.set_text(std::to_string(::getpid()) + "\n");
  BatchOutcome outcome;
  for (size_t i = 0; i < items.size(); ++i)
    outcome.items += o.shard.takes(i);
  using Clock = std::chrono::steady_clock;
  Clock::time_point summary_due = Clock::now() + kSummaryEvery;
  auto summarise = [&] {
    const Clock::time_point t0 = Clock::now();
    try {
      write_batch_summary(items, o.out_dir);
    } catch (const Error& e) {
      if (o.say) o.say(std::string("cannot write the summary: ") + e.what());
    }
    const Clock::time_point t1 = Clock::now();
    summary_due = t1 + std::max<Clock::duration>(kSummaryEvery, (t1 - t0) * kSummaryTimeShare);
  };
  int position = 0;
  for (size_t i = 0; i < items.size(); ++i) {
    if (!o.shard.takes(i)) continue;
    if (o.cancelled && o.cancelled()) {
      outcome.interrupted = true;
      break;
    }
    ++position;
    const BatchItem& item = items[i];
    const fs::path dir = o.out_dir / item.id;
    fs::create_directories(dir / ".svgmotion", ec);  // a run directory (run_directory.h): batch.log goes in first
    const std::string tag = "[" + std::to_string(position) + "/" + std::to_string(outcome.items) + "] " + item.id;
    if (o.say) o.say(tag + ": running");
    const std::optional<BatchItemResult> before = read_record(dir / kRecord);
    std::vector<std::string> argv = batch_run_argv(item, o);
    argv.insert(argv.begin(), o.program.string());
    CommandResult r;
    BatchItemResult res;
    try {
      const auto say_item = [&](const std::string& line) {
        if (o.say) o.say(tag + ": " + line);
      };
      if (!wait_for_earlier_run(dir, o.cancelled, say_item)) {
        res.id = item.id;
        res.status = "interrupted";
        res.reason = "stopped; run the batch again to resume";
      } else {
        r = run_command(argv, dir / kLog, 0, o.cancelled);
        res = judge(item, r, dir, before);
      }
    } catch (const Error& e) {  // the log could not be created: the item fails, the batch goes on
      res.id = item.id;
      res.status = "failed";
      res.reason = e.what();
    }
    nlohmann::json record = to_json(res);
    record["input"] = item.input.string();
    record["finished"] = utc_now();
    record["host"] = host_name();
    record["shard"] = o.shard.name();
    try {
      write_file_atomic(dir / kRecord, dump(record));
    } catch (const Error& e) {
      if (o.say) o.say(tag + ": cannot write its record: " + e.what());
    }
    if (Clock::now() >= summary_due) summarise();
    (res.status == "done" ? outcome.done : outcome.not_done) += 1;
    if (o.say) {
      std::string line = tag + ": " + res.status;
      if (res.status == "done" && res.reason.empty()) line += " in " + number(res.seconds, 1) + " s";
      if (res.psnr_db) line += ", worst keyframe " + number(res.psnr_db, 1) + " dB";
      if (!res.reason.empty()) line += " (" + res.reason + ")";
      o.say(line);
    }
    if (res.status == "interrupted") {
      outcome.interrupted = true;
      break;
    }
  }
  summarise();
  return outcome;
}

void follow_batch_parent() {
  const char* v = std::getenv(kParentVariable);
  if (!v) return;
  char* end = nullptr;
  const long parent = std::strtol(v, &end, 10);
  const bool valid = end != v && *end == '\0' && parent > 1 && parent <= INT_MAX;
  // Not for this process's own children (a video generator, a nested svgmotion): their parent
  // is this run, which ends them itself.
  ::unsetenv(kParentVariable);
  if (!valid) return;
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  // The batch may have died between starting us and the prctl: then our parent is already
  // init (or a subreaper) and no signal would come.
  if (::getppid() != static_cast<pid_t>(parent)) ::raise(SIGTERM);
}

void mark_batch_parent() { ::setenv(kParentVariable, std::to_string(::getpid()).c_str(), 1); }

}  // namespace svgm
