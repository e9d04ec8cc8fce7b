// hosted_session.h: deadlines, retries and one-line errors for hosted video generators.
#include "generators/hosted_session.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <thread>

#include <unistd.h>

#include "net/secret_scrub.h"
#include "plugin/plugin_options.h"
#include "svgmotion/error.h"
#include "svgmotion/target_video.h"
#include "generators/command_runner.h"

namespace svgm {

namespace fs = std::filesystem;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

// The longest pause one cancel check waits through (s): Ctrl-C is seen within this.
constexpr double kCancelCheckS = 0.1;

// Each poll of a job waits this much longer than the one before: a hosted video takes from
// ~10 s to several minutes (Google's Veo examples poll every 10 s), so early polls are cheap
// and late ones need not be frequent.
constexpr double kPollGrowth = 1.5;

const char* const kVideoExtensions[] = {"mp4", "webm", "gif", "mov", "mkv", "avi", "m4v", "webp"};

// A refused credential: no retry, and the message says which variable held it. 401 and 403 are
// HTTP's; the Gemini API answers a malformed or unknown key with 400 and reason API_KEY_INVALID.
bool key_refused(const HttpReply& r) {
  return r.status == 401 || r.status == 403 ||
         (r.status == 400 && r.body.find("API_KEY_INVALID") != std::string::npos);
}

bool retryable(const HttpReply& r) {
  return !r.connected || r.status >= 500 || r.status == 429 || r.status == 408;
}

}  // namespace

std::string one_line(std::string s, size_t max_chars) {
  for (char& c : s)  // newlines, tabs, and the escape sequences a hostile server could send a terminal
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  if (s.size() > max_chars) s = s.substr(0, max_chars) + "...";
  return s;
}

std::string reply_message(const std::string& raw, const std::string& secret) {
  // Scrubbed whole before anything is cut: a key straddling the cut would otherwise survive in
  // part.
  const std::string body = scrub_secret(raw, secret);
  auto shown = [](const std::string& s) { return safe_excerpt(s, "", 200); };
  const json j = json::parse(body, nullptr, false);
  if (j.is_object()) {
    if (j.contains("error")) {
      const json& e = j["error"];
      if (e.is_string()) return shown(e.get<std::string>());
      if (e.is_object() && e.contains("message") && e["message"].is_string())
        return shown(e["message"].get<std::string>());
    }
    for (const char* key : {"detail", "message"})
      if (j.contains(key) && j[key].is_string()) return shown(j[key].get<std::string>());
  }
  return shown(body);
}

double retry_after_seconds(const std::string& value) {
  if (value.empty() || !std::all_of(value.begin(), value.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || c == '.';
      }))
    return -1;
  try {
    return std::stod(value);
  } catch (const std::exception&) {
    return -1;
  }
}

SessionLimits read_session_limits(const PluginOptions& opt, const SessionLimits& d) {
  SessionLimits l = d;
  l.timeout_s = opt.number("timeout_s", d.timeout_s);
  if (l.timeout_s <= 0) opt.fail("options.timeout_s must be > 0 seconds");
  l.retries = opt.whole("retries", d.retries, 0, 10);
  l.poll_s = opt.number("poll_s", d.poll_s);
  if (l.poll_s <= 0 || l.poll_s > 600) opt.fail("options.poll_s must be in (0, 600] seconds");
  l.poll_max_s = opt.number("poll_max_s", std::max(d.poll_max_s, l.poll_s));
  if (l.poll_max_s < l.poll_s || l.poll_max_s > 600) opt.fail("options.poll_max_s must be in [poll_s, 600] seconds");
  l.max_video_bytes = static_cast<uint64_t>(opt.whole("max_video_mib", static_cast<int>(d.max_video_bytes >> 20), 1, 65536)) << 20;
  return l;
}

bool is_video_extension(const std::string& ext) {
  for (const char* e : kVideoExtensions)
    if (ext == e) return true;
  return false;
}

std::string two_digits(int i) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d", i);
  return buf;
}

HostedSession::HostedSession(std::string who, std::string label, const SessionLimits& limits,
                             HttpTransport& http, const HostedHooks& hooks, SessionSecret secret)
    : who_(std::move(who)), label_(std::move(label)), limits_(limits), http_(http), hooks_(hooks),
      secret_(std::move(secret)),
      end_(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(limits.timeout_s))),
      poll_pause_(limits.poll_s) {}

void HostedSession::wait_to_poll(const std::string& url) {
  pause(poll_pause_);
  if (left() <= 0) timeout(url);
  poll_pause_ = std::min(poll_pause_ * kPollGrowth, limits_.poll_max_s);
}

double HostedSession::left() const {
  return std::chrono::duration<double>(end_ - Clock::now()).count();
}

std::string HostedSession::scrub(std::string s) const { return scrub_secret(std::move(s), secret_.value); }

std::string HostedSession::excerpt(const std::string& s, size_t max_chars) const {
  return safe_excerpt(s, secret_.value, max_chars);
}

void HostedSession::fail(const std::string& message) const {
  throw Error(scrub(who_ + ": " + label_ + message));
}

void HostedSession::timeout(const std::string& url) const {
  fail("no result within " + short_number(limits_.timeout_s) + " s (" +
       (job.empty() ? "waiting for " + url : job) + ")");
}

void HostedSession::check_cancelled() const {
  if (hooks_.cancelled && hooks_.cancelled()) fail("cancelled");
}

void HostedSession::log(const std::string& line) const {
  if (hooks_.log) hooks_.log(scrub(who_ + ": " + label_ + line));
}

void HostedSession::pause(double seconds) const {
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(std::min(seconds, left())));
  while (Clock::now() < until) {
    check_cancelled();
    const double step = std::min(std::chrono::duration<double>(until - Clock::now()).count(), kCancelCheckS);
    if (step <= 0) break;
    if (hooks_.sleep) hooks_.sleep(step);
    else std::this_thread::sleep_for(std::chrono::duration<double>(step));
  }
}

template <class Send>
HttpReply HostedSession::request(const std::string& url, Send&& send) {
  // Whoever named the URL (a submit reply's status_url, a result's video URL), only http and
  // https are fetched: file: would read a local file, dict: or gopher: talk to a local port.
  // The URL itself is not shown: a server-given one may carry a token.
  if (!is_http_url(url)) fail("refused to fetch " + scheme_for_message(url) + " (only http and https)");
  for (int attempt = 0;; ++attempt) {
    check_cancelled();
    const double budget = left();
    if (budget <= 0) timeout(url);
    HttpReply r = send(budget);
    check_cancelled();
    if (r.timed_out) timeout(url);
    if (r.refused) fail(r.error);
    if (r.connected && r.status >= 200 && r.status < 300) {
      r.body = scrub(std::move(r.body));  // nothing derived from a reply can show the key
      return r;
    }
    std::string why = r.connected ? "HTTP " + std::to_string(r.status) + " from " + url
                                  : "cannot connect to " + url + ": " + one_line(r.error);
    const std::string message = r.connected ? reply_message(r.body, secret_.value) : "";
    if (!message.empty()) why += ": " + message;
    if (r.connected && key_refused(r) && !secret_.env.empty())
      fail("the API key in $" + secret_.env + " was refused: " + why);
    if (!retryable(r) || attempt >= limits_.retries) fail(why);
    // A rate limit names its own pause; waiting less would only be refused again.
    const double asked = r.status == 429 ? retry_after_seconds(r.header("retry-after")) : -1;
    const double wait = asked >= 0 ? asked : limits_.backoff_s * std::pow(2.0, attempt);
    if (left() <= wait)
      fail(why + (asked >= 0 ? "; the server asks to retry after " + short_number(asked) +
                                   " s, past the candidate's time limit of " +
                                   short_number(limits_.timeout_s) + " s"
                             : ""));
    log(why + "; retrying in " + short_number(wait) + " s");
    pause(wait);
  }
}

std::string HostedSession::get(const std::string& url) {
  return request(url, [&](double t) { return http_.get(url, t); }).body;
}

std::string HostedSession::post_json(const std::string& url, const std::string& body) {
  return request(url, [&](double t) { return http_.post_json(url, body, t); }).body;
}

std::string HostedSession::post_file(const std::string& url, const std::string& field,
                                     const fs::path& file) {
  return request(url, [&](double t) { return http_.post_file(url, field, file, t); }).body;
}

void HostedSession::download(const std::string& url, const fs::path& file, const std::string& shown) {
  request(url, [&](double t) {
    HttpReply r = http_.download(url, file, limits_.max_video_bytes, t);
    // A write the disk refuses is no reason to retry, nor a connection problem.
    if (!r.write_error.empty()) fail(shown + ": cannot write: " + r.write_error);
    return r;
  });
}

json HostedSession::parse(const std::string& url, const std::string& body) const {
  json j = json::parse(body, nullptr, false);
  if (j.is_discarded()) fail("malformed JSON from " + url + ": " + excerpt(body, 120));
  return j;
}

namespace {

// Removes a download's temporary file unless it was renamed into place.
struct PartFile {
  fs::path path;
  ~PartFile() {
    std::error_code ec;
    if (!path.empty()) fs::remove(path, ec);
  }
};

}  // namespace

void download_candidate_video(HostedSession& s, const std::string& url, const fs::path& out,
                              const std::string& out_rel) {
  // A hidden name beside `out` keeping its extension (the probe reads it); the pid keeps two
  // runs in one folder apart, the candidate number in the name keeps candidates apart.
  PartFile part{out.parent_path() / ("." + out.stem().string() + ".part" + std::to_string(::getpid()) +
                                     out.extension().string())};
  s.download(url, part.path, out_rel);
  std::string why;
  try {
    const TargetInfo info = probe_target(part.path);
    if (info.frames < 1) why = "it has no frames";
    else
      s.log(out_rel + ": " + std::to_string(info.frames) + " frames of " + std::to_string(info.width) +
            "x" + std::to_string(info.height) + " at " + short_number(info.fps) + " fps");
  } catch (const Error& e) {
    why = e.what();
    const std::string prefix = part.path.string() + ": ";
    if (why.rfind(prefix, 0) == 0) why = why.substr(prefix.size());
  }
  if (!why.empty()) s.fail("the result of " + s.job + " (" + out_rel + ") is not a readable video: " + one_line(why));
  std::error_code ec;
  fs::rename(part.path, out, ec);
  if (ec) s.fail(out_rel + ": cannot write: " + ec.message());
  part.path.clear();
}

std::string read_recolored_png(const fs::path& run_dir, const std::string& who) {
  const fs::path file = run_dir / "recolored.png";
  std::ifstream f(file, std::ios::binary);
  if (!f || !fs::is_regular_file(file))
    throw Error(who + ": " + file.string() + ": no such file (the recoloured image)");
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

std::string video_prompt(const std::string& prompt_template, const std::string& prompt) {
  std::string full = replace_placeholder(prompt_template, "prompt", prompt);
  while (!full.empty() && (full.back() == ' ' || full.back() == '\n')) full.pop_back();
  return full;
}

bool is_http_url(const std::string& u) {
  const std::string scheme = url_scheme(u);
  return (scheme == "http" || scheme == "https") && u.compare(scheme.size(), 3, "://") == 0;
}

fs::path reset_candidates_dir(const fs::path& run_dir, const std::string& who) {
  const fs::path dir = run_dir / "candidates";
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (ec) throw Error(who + ": " + dir.string() + ": cannot empty: " + ec.message());
  fs::create_directories(dir, ec);
  if (ec) throw Error(who + ": " + dir.string() + ": cannot create: " + ec.message());
  return dir;
}

}  // namespace svgm
