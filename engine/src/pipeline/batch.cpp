// Running a batch of items, one `svgmotion run` process each (see batch.h).
#include "pipeline/batch.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"
#include "video/command_runner.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRecord = "batch.json";  // an item's record, in its run directory
constexpr const char* kLog = "batch.log";      // the item's `svgmotion run` output

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
// process dies).
class FileLock {
 public:
  explicit FileLock(const fs::path& file) {
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw Error(file.string() + ": cannot open the summary lock: " + std::strerror(errno));
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) {
        ::close(fd_);
        throw Error(file.string() + ": cannot lock: " + std::strerror(errno));
      }
  }
  ~FileLock() { ::close(fd_); }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_ = -1;
};

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

std::vector<BatchItemResult> write_batch_summary(const std::vector<BatchItem>& items, const fs::path& out) {
  const FileLock lock(out / ".summary.lock");
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
  write_file_atomic(out / "summary.csv", csv);
  write_file_atomic(out / "summary.json", summary.dump(2) + "\n");
  return rows;
}

BatchOutcome run_batch(const std::vector<BatchItem>& items, const BatchOptions& o) {
  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  if (ec) throw Error(o.out_dir.string() + ": cannot create: " + ec.message());
  BatchOutcome outcome;
  for (size_t i = 0; i < items.size(); ++i)
    outcome.items += o.shard.takes(i);
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
      r = run_command(argv, dir / kLog, 0, o.cancelled);
      res = judge(item, r, dir, before);
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
      write_file_atomic(dir / kRecord, record.dump(2) + "\n");
      write_batch_summary(items, o.out_dir);
    } catch (const Error& e) {
      if (o.say) o.say(tag + ": cannot write its record: " + e.what());
    }
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
  if (outcome.items == 0) write_batch_summary(items, o.out_dir);
  return outcome;
}

}  // namespace svgm
