// candidate_pool.h: candidates made on worker threads, hooks called from the caller's thread.
#include "generators/candidate_pool.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>

#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

// How often the calling thread polls the cancel check and forwards progress (s).
constexpr double kPollS = 0.1;

struct Shared {
  std::mutex m;
  std::condition_variable wake;
  std::deque<std::pair<bool, std::string>> lines;  // (warning, line)
  std::vector<double> fraction;                    // per candidate
  std::string note;
  bool progressed = false;
  int finished = 0;
  std::atomic<bool> cancelled{false};
};

}  // namespace

std::vector<fs::path> make_candidates(const std::string& who, int n, int concurrency,
                                      const HostedHooks& hooks, const MakeCandidate& make) {
  Shared sh;
  sh.fraction.assign(static_cast<size_t>(n), 0.0);
  std::vector<std::optional<fs::path>> files(static_cast<size_t>(n));
  std::vector<std::string> errors(static_cast<size_t>(n));
  std::atomic<int> next{0};

  auto worker = [&] {
    for (int i = next++; i < n; i = next++) {
      HostedHooks h;
      h.sleep = hooks.sleep;
      h.cancelled = [&sh] { return sh.cancelled.load(); };
      h.log = [&sh](const std::string& line) {
        std::lock_guard<std::mutex> lock(sh.m);
        sh.lines.emplace_back(false, line);
      };
      h.warn = [&sh](const std::string& line) {
        std::lock_guard<std::mutex> lock(sh.m);
        sh.lines.emplace_back(true, line);
      };
      h.progress = [&sh, i, n](double f, const std::string& note) {
        std::lock_guard<std::mutex> lock(sh.m);
        sh.fraction[static_cast<size_t>(i)] = std::clamp(f, 0.0, 1.0);
        sh.note = "candidate " + std::to_string(i + 1) + " of " + std::to_string(n) + ": " + note;
        sh.progressed = true;
      };
      std::string error;
      std::optional<fs::path> file;
      try {
        file = make(i, h);
      } catch (const std::exception& e) {  // an Error, or bad_alloc and the like: still one line
        error = e.what();
      }
      std::lock_guard<std::mutex> lock(sh.m);
      files[static_cast<size_t>(i)] = file;
      errors[static_cast<size_t>(i)] = error;
      if (error.empty()) sh.fraction[static_cast<size_t>(i)] = 1.0;
      ++sh.finished;
      sh.wake.notify_all();
    }
  };

  std::vector<std::thread> threads;
  for (int t = 0; t < std::clamp(concurrency, 1, std::max(1, n)); ++t) threads.emplace_back(worker);

  // The calling thread: forward what the workers queued, pass on a cancel.
  for (;;) {
    std::deque<std::pair<bool, std::string>> lines;
    std::optional<std::pair<double, std::string>> progress;
    bool done = false;
    {
      std::unique_lock<std::mutex> lock(sh.m);
      sh.wake.wait_for(lock, std::chrono::duration<double>(kPollS));
      lines.swap(sh.lines);
      if (sh.progressed) {
        double sum = 0;
        for (double f : sh.fraction) sum += f;
        progress = {{sum / n, sh.note}};
        sh.progressed = false;
      }
      done = sh.finished == n;
    }
    for (const auto& [warning, line] : lines) {
      if (warning && hooks.warn) hooks.warn(line);
      else if (hooks.log) hooks.log(line);
    }
    if (progress && hooks.progress) hooks.progress(progress->first, progress->second);
    if (!sh.cancelled && hooks.cancelled && hooks.cancelled()) sh.cancelled = true;
    if (done) break;
  }
  for (auto& t : threads) t.join();

  if (sh.cancelled) throw Error(who + ": cancelled");
  std::vector<fs::path> out;
  std::string first;
  for (int i = 0; i < n; ++i)
    if (files[static_cast<size_t>(i)]) out.push_back(*files[static_cast<size_t>(i)]);
    else if (first.empty()) first = errors[static_cast<size_t>(i)];
  if (n == 1 && out.empty()) throw Error(first);
  // Every failure, in index order, one line each: the user sees which candidates are missing.
  for (int i = 0; i < n; ++i) {
    if (files[static_cast<size_t>(i)]) continue;
    const std::string& e = errors[static_cast<size_t>(i)];
    if (hooks.warn) hooks.warn(e);
    else if (hooks.log) hooks.log(e);
  }
  if (out.empty())
    throw Error(who + ": all " + std::to_string(n) + " candidates failed (the first: " + first + ")");
  if (hooks.progress) hooks.progress(1.0, "done");
  return out;
}

}  // namespace svgm
