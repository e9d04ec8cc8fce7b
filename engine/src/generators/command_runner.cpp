#include "generators/command_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/types.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <thread>

#include "svgmotion/error.h"

extern char** environ;

namespace svgm {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Shell-style quoting, only for the log's first line (the command is never run through a shell).
std::string quoted(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789_-+=/.,:@%") == std::string::npos)
    return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void write_all(int fd, const std::string& text) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the log is best effort once the program runs
    p += n;
    left -= static_cast<size_t>(n);
  }
}

// RAII for the spawn attribute objects.
struct SpawnSetup {
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  SpawnSetup() {
    posix_spawn_file_actions_init(&actions);
    posix_spawnattr_init(&attr);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

// wait4 that retries on EINTR; returns the pid, 0 (still running, WNOHANG) or -1. `usage`
// gets the reaped program's resource use (its peak memory).
pid_t wait_for(pid_t pid, int* status, int flags, struct rusage* usage) {
  for (;;) {
    const pid_t r = ::wait4(pid, status, flags, usage);
    if (r < 0 && errno == EINTR) continue;
    return r;
  }
}

bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Ctrl-C (or SIGTERM/SIGHUP) while a program runs: the program sits in its own process group,
// so the terminal's SIGINT does not reach it. The handler only notes the signal; the wait loop
// stops the group, restores the host's handlers and raises the signal again for them.
volatile sig_atomic_t g_interrupt = 0;

extern "C" void note_interrupt(int sig) { g_interrupt = sig; }

class InterruptGuard {
 public:
  InterruptGuard() {
    g_interrupt = 0;
    struct sigaction sa {};
    sa.sa_handler = note_interrupt;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < kCount; ++i) {
      installed_[i] = false;
      if (::sigaction(kSignals[i], nullptr, &old_[i]) != 0) continue;
      if (old_[i].sa_handler == SIG_IGN) continue;  // the host ignores it: so do we
      installed_[i] = ::sigaction(kSignals[i], &sa, nullptr) == 0;
    }
  }
  ~InterruptGuard() {
    for (size_t i = 0; i < kCount; ++i)
      if (installed_[i]) ::sigaction(kSignals[i], &old_[i], nullptr);
    const int sig = g_interrupt;
    g_interrupt = 0;
    if (sig != 0) ::raise(sig);  // now handled as the host would have
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  static int pending() { return g_interrupt; }

 private:
  static constexpr size_t kCount = 3;
  static constexpr int kSignals[kCount] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction old_[kCount];
  bool installed_[kCount];
};

}  // namespace

std::string short_number(double value) {
  if (std::isfinite(value) && value == std::round(value) && std::fabs(value) < 1e15)
    return std::to_string(static_cast<long long>(value));
  std::ostringstream s;
  s.precision(6);
  s << value;
  return s.str();
}

CommandResult run_command(const std::vector<std::string>& argv, const std::filesystem::path& log,
                          double timeout_s, const std::function<bool()>& cancelled) {
  if (argv.empty() || argv[0].empty()) throw Error("run_command: empty argv");

  const int log_fd =
      ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (log_fd < 0) throw Error(log.string() + ": cannot create the log: " + std::strerror(errno));
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{log_fd};

  std::string header = "# svgmotion:";
  for (const auto& a : argv) header += " " + quoted(a);
  write_all(log_fd, header + "\n");

  std::vector<char*> cargv;
  cargv.reserve(argv.size() + 1);
  for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
  cargv.push_back(nullptr);

  SpawnSetup setup;
  posix_spawn_file_actions_addopen(&setup.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&setup.actions, log_fd, 1);
  posix_spawn_file_actions_adddup2(&setup.actions, log_fd, 2);
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 34))
  // The host's own descriptors (OpenCL drivers, sockets) are none of the program's business.
  posix_spawn_file_actions_addclosefrom_np(&setup.actions, 3);
#endif
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  posix_spawnattr_setsigmask(&setup.attr, &none);  // the host may block signals in its thread
  posix_spawnattr_setsigdefault(&setup.attr, &all);  // and ignore some (SIGPIPE)
  posix_spawnattr_setpgroup(&setup.attr, 0);        // a group of its own, killed as one
  posix_spawnattr_setflags(&setup.attr, static_cast<short>(POSIX_SPAWN_SETPGROUP |
                                                           POSIX_SPAWN_SETSIGMASK |
                                                           POSIX_SPAWN_SETSIGDEF));

  CommandResult result;
  InterruptGuard interrupts;  // before the spawn, so no Ctrl-C is missed
  const auto t0 = Clock::now();
  pid_t pid = -1;
  const int rc = ::posix_spawnp(&pid, cargv[0], &setup.actions, &setup.attr, cargv.data(), environ);
  if (rc != 0) {
    result.spawn_error = std::string(std::strerror(rc));
    result.seconds = seconds_since(t0);
    write_all(log_fd, "# svgmotion: " + argv[0] + " " + describe(result, timeout_s) + "\n");
    return result;
  }

  int status = 0;
  struct rusage usage {};
  bool stopping = false;  // SIGTERM sent
  Clock::time_point term_time{};
  bool killed = false;
  for (;;) {
    const pid_t r = wait_for(pid, &status, WNOHANG, &usage);
    if (r == pid) {
      result.peak_rss_kb = usage.ru_maxrss;  // kilobytes on Linux
      break;
    }
    if (r < 0) {  // cannot happen for our own child; do not spin
      result.spawn_error = std::string("waitpid: ") + std::strerror(errno);
      ::kill(-pid, SIGKILL);
      result.seconds = seconds_since(t0);
      return result;
    }
    if (!stopping) {
      if (timeout_s > 0 && seconds_since(t0) >= timeout_s) result.timed_out = true;
      else if (InterruptGuard::pending() != 0 || (cancelled && cancelled())) result.cancelled = true;
      if (result.timed_out || result.cancelled) {
        ::kill(-pid, SIGTERM);
        stopping = true;
        term_time = Clock::now();
      }
    } else if (!killed && seconds_since(term_time) >= 2.0) {
      ::kill(-pid, SIGKILL);
      killed = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  // Stragglers of a stopped group (children that ignored SIGTERM) go now; the group id cannot
  // have been reused while any member lives.
  if (stopping) ::kill(-pid, SIGKILL);

  result.seconds = seconds_since(t0);
  if (WIFEXITED(status)) {
    result.status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signalled = true;
    result.signal = WTERMSIG(status);
  }
  std::ostringstream footer;
  footer << "# svgmotion: " << argv[0] << " " << describe(result, timeout_s) << " ("
         << short_number(std::round(result.seconds * 10) / 10) << " s)\n";
  write_all(log_fd, footer.str());
  return result;
}

std::string describe(const CommandResult& r, double timeout_s) {
  if (!r.spawn_error.empty()) return "could not be started: " + r.spawn_error;
  if (r.timed_out) return "timed out after " + short_number(timeout_s) + " s";
  if (r.cancelled) return "was cancelled";
  if (r.signalled) {
    const char* name = ::strsignal(r.signal);
    return "was killed by signal " + std::to_string(r.signal) +
           (name ? std::string(" (") + name + ")" : std::string());
  }
  return "exited with status " + std::to_string(r.status);
}

std::string replace_placeholder(const std::string& text, const std::string& key,
                                const std::string& value) {
  const std::string token = "{" + key + "}";
  std::string out;
  size_t pos = 0;
  for (;;) {
    const size_t hit = text.find(token, pos);
    if (hit == std::string::npos) break;
    out.append(text, pos, hit - pos);
    out += value;
    pos = hit + token.size();
  }
  out.append(text, pos, std::string::npos);
  return out;
}

std::vector<std::string> expand_argv(const std::vector<std::string>& argv_template,
                                     const std::map<std::string, std::string>& values) {
  std::vector<std::string> out;
  out.reserve(argv_template.size());
  for (size_t i = 0; i < argv_template.size(); ++i) {
    const std::string& t = argv_template[i];
    std::string arg;
    size_t pos = 0;
    while (pos < t.size()) {
      const size_t open = t.find('{', pos);
      if (open == std::string::npos) break;
      size_t end = open + 1;
      const bool starts_name =
          end < t.size() && is_name_char(t[end]) && !(t[end] >= '0' && t[end] <= '9');
      while (starts_name && end < t.size() && is_name_char(t[end])) ++end;
      if (end == open + 1 || end >= t.size() || t[end] != '}') {  // not a placeholder: literal
        arg.append(t, pos, open + 1 - pos);
        pos = open + 1;
        continue;
      }
      const std::string name = t.substr(open + 1, end - open - 1);
      const auto it = values.find(name);
      if (it == values.end()) {
        std::string known;
        for (const auto& [k, v] : values) known += (known.empty() ? "{" : ", {") + k + "}";
        throw Error("unknown placeholder {" + name + "} in argv[" + std::to_string(i) +
                    "] (known: " + known + ")");
      }
      arg.append(t, pos, open - pos);
      arg += it->second;
      pos = end + 1;
    }
    arg.append(t, std::min(pos, t.size()), std::string::npos);
    out.push_back(std::move(arg));
  }
  return out;
}

}  // namespace svgm
