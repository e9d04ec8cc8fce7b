// Run directories (see run_directory.h).
#include "run/run_directory.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "run/stage_files.h"
#include "svgmotion/atomic_file.h"
#include "svgmotion/temporary_name.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMarker = ".svgmotion";

// "Read-only file system" -> "read-only file system": the reason inside our own sentence.
std::string reason(int err) {
  std::string r = std::strerror(err);
  if (!r.empty() && r[0] >= 'A' && r[0] <= 'Z' && (r.size() < 2 || !(r[1] >= 'A' && r[1] <= 'Z'))) r[0] = static_cast<char>(r[0] - 'A' + 'a');
  return r;
}

[[noreturn]] void cannot_write(const fs::path& dir, int err) {
  throw Error(dir.string() + ": cannot write (" + reason(err) + ")");
}

// Whether process `pid` has ended (a temporary file of a running one is still being written);
// one of this process's pid is an old one's, since nothing was written before the lock.
bool gone(long pid) { return pid == ::getpid() || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH); }

}  // namespace

const std::vector<std::string>& fit_output_names() {
  static const std::vector<std::string> names = {"animation.svg", "animation.failed.svg", "animation.json",
                                                 "animation.failed.json", "animation.lottie",
                                                 "animation.failed.lottie", "preview.mp4", "fit.json",
                                                 "checkpoint.bin"};
  return names;
}

const std::vector<std::string>& run_output_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"input.svg", "log.txt", "report.html", "motion.json", "resolved.yaml"};
    for (const StageFiles& sf : stage_files())
      for (const auto& [k, v] : sf.outputs.items()) n.push_back(v.get<std::string>());
    for (const std::string& f : fit_output_names())
      if (std::find(n.begin(), n.end(), f) == n.end()) n.push_back(f);
    return n;
  }();
  return names;
}

void claim_run_directory(const fs::path& dir, bool force, const std::vector<std::string>& ours) {
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (!ec && fs::exists(st) && !fs::is_directory(st)) throw Error(dir.string() + ": not a folder");
  if (!fs::exists(st)) {
    // Each missing parent in turn, so the error names the one that could not be made.
    fs::path made;
    for (const fs::path& part : dir) {
      made /= part;
      if (::mkdir(made.c_str(), 0777) != 0 && errno != EEXIST) cannot_write(made, errno);
    }
  }
  if (fs::is_directory(dir / kMarker, ec)) return;
  size_t entries = 0;
  std::string taken;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    ++entries;
    const std::string name = e.path().filename().string();
    if (taken.empty() && std::find(ours.begin(), ours.end(), name) != ours.end()) taken = name;
  }
  if (ec) throw Error(dir.string() + ": cannot read: " + ec.message());
  if (entries > 0 && !force)
    throw Error(dir.string() + ": not a svgmotion run directory and not empty (" + std::to_string(entries) +
                (entries == 1 ? " entry" : " entries") + "); choose an empty folder or pass --force");
  if (!taken.empty())
    throw Error((dir / taken).string() + ": not written by svgmotion, and a run would replace it; move it "
                "away or choose an empty folder");
  if (::mkdir((dir / kMarker).c_str(), 0777) != 0 && errno != EEXIST) cannot_write(dir, errno);
}

RunLock::RunLock(const fs::path& dir, bool force, const std::vector<std::string>& ours) {
  claim_run_directory(dir, force, ours);
  const fs::path file = dir / kMarker / "lock";
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    if (errno == EROFS || errno == EACCES || errno == EPERM) cannot_write(dir, errno);
    throw Error(dir.string() + ": cannot lock the run directory: " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    char pid[32] = {0};
    const ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
    ::close(fd_);
    throw Error(dir.string() + ": another svgmotion run is using this run directory" +
                (n > 0 ? " (pid " + std::string(pid, static_cast<size_t>(n)) + ")" : std::string()));
  }
  const std::string me = std::to_string(::getpid());
  if (::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, me.data(), me.size(), 0) < 0) {}
  // Only names of our own temporaries (".NAME.svgm-tmp-PID"), of processes that have ended.
  std::error_code ec;
  for (const fs::path& d : {dir, dir / "candidates"})
    for (const auto& e : fs::directory_iterator(d, ec)) {
      const long pid = temporary_name_pid(e.path().filename().native());
      if (pid > 0 && gone(pid)) fs::remove_all(e.path(), ec);
    }
}

RunLock::~RunLock() { ::close(fd_); }

}  // namespace svgm
