// One candidate's exchanges with a hosted video generator (ComfyUI, the Gemini API's Veo, a
// queue-style HTTP API) under one deadline: each request retried with backoff for connection
// errors, HTTP 5xx and rate limiting (429, honouring Retry-After), pauses that wake for a
// cancel and never pass the deadline, one-line errors naming the candidate, and the API key
// scrubbed from every reply as it arrives and from every message (a server may echo it; see
// net/secret_scrub.h). Only http and https URLs are fetched, whoever named them (the config, a
// submit reply's status_url, a result's video URL); videos stream to disk under a size limit.
// The clients (comfyui_client, veo_client, http_job_client) keep only what their API adds:
// URLs, bodies, replies.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "net/http_transport.h"
#include "generators/generator_hooks.h"

namespace svgm {

struct HostedHooks : GeneratorHooks {
  std::function<void(double seconds)> sleep;  // empty = std::this_thread::sleep_for
};

struct SessionLimits {
  double timeout_s = 600;  // the whole candidate: submit, poll, download
  int retries = 2;         // per request, for connection errors, 5xx and 429
  // The first retry's pause when the server names none; doubled each retry.
  double backoff_s = 0.5;
  // The first pause between polls of a job; each grows by half, up to poll_max_s.
  double poll_s = 1, poll_max_s = 1;
  // The largest video a download may bring (bytes); past it the transfer is aborted. A hosted
  // 8 s 720p clip is a few MB; 2 GiB stops a server that streams without end before the disk
  // fills.
  uint64_t max_video_bytes = uint64_t{2} << 30;
};

class PluginOptions;

// Reads options timeout_s (> 0), retries (0..10), poll_s (0..600], poll_max_s [poll_s, 600]
// and max_video_mib (1..65536), each defaulting to `defaults`' (poll_max_s to at least poll_s).
SessionLimits read_session_limits(const PluginOptions& opt, const SessionLimits& defaults);

// The credential a session must never show: the key's value (scrubbed from messages) and the
// environment variable it came from (named when the server refuses it).
struct SessionSecret {
  std::string value;
  std::string env;
};

class HostedSession {
 public:
  // `who` is the plugin ("video veo"), `label` the candidate ("candidate 03: ").
  HostedSession(std::string who, std::string label, const SessionLimits& limits,
                HttpTransport& http, const HostedHooks& hooks, SessionSecret secret = {});

  // What is being waited for once known ("prompt 1234", "operation models/x/operations/y"),
  // named in a timeout.
  std::string job;

  double left() const;
  [[noreturn]] void fail(const std::string& message) const;  // "<who>: <label><message>"
  [[noreturn]] void timeout(const std::string& url) const;
  void check_cancelled() const;
  void pause(double seconds) const;  // up to `seconds`, never past the deadline
  // Waits before the next poll of `url` (the pause grows each call); a timeout once the
  // deadline has passed.
  void wait_to_poll(const std::string& url);
  void log(const std::string& line) const;  // "<who>: <label><line>", if the host listens

  // The body of a 2xx answer to GET / POST `url`, after retries, with the secret scrubbed
  // out; fails with one line otherwise ("HTTP 403 from URL: <the server's message>", "cannot
  // connect to URL: <why>", "the API key in $ENV was refused: HTTP 401 from ...", "refused to
  // fetch a file: URL (only http and https)", "the reply from HOST is larger than 16 MiB").
  std::string get(const std::string& url);
  std::string post_json(const std::string& url, const std::string& body);
  std::string post_file(const std::string& url, const std::string& field,
                        const std::filesystem::path& file);
  // GET `url` into `file` (at most limits.max_video_bytes), after retries; fails as get() does,
  // or with "<shown>: cannot write: <why>" when the file cannot be written (a full disk).
  void download(const std::string& url, const std::filesystem::path& file, const std::string& shown);

  nlohmann::json parse(const std::string& url, const std::string& body) const;

  // `s` without the secret (verbatim or encoded, net/secret_scrub.h).
  std::string scrub(std::string s) const;
  // What may be shown of a server's text: scrubbed, then on one line and cut to max_chars.
  std::string excerpt(const std::string& s, size_t max_chars = 200) const;

 private:
  template <class Send>
  HttpReply request(const std::string& url, Send&& send);

  std::string who_, label_;
  SessionLimits limits_;
  HttpTransport& http_;
  const HostedHooks& hooks_;
  SessionSecret secret_;
  std::chrono::steady_clock::time_point end_;
  double poll_pause_;
};

// s on one line (control characters as spaces, trailing spaces dropped), cut to max_chars.
std::string one_line(std::string s, size_t max_chars = 200);

// The human part of an error answer: error.message, error (a string), detail or message of a
// JSON body (Google, OpenAI, FastAPI/fal, Replicate shapes), else the body; `secret` scrubbed
// from the whole body first, then on one line (control characters as spaces), cut to 200.
std::string reply_message(const std::string& body, const std::string& secret = "");

// Seconds a Retry-After header asks for (delta-seconds; an HTTP date or garbage gives -1).
double retry_after_seconds(const std::string& value);

// Whether a file extension (lower case, no dot) is a video container a generator may return.
bool is_video_extension(const std::string& ext);

// "00", "01", ... (candidate file names).
std::string two_digits(int i);

// Downloads `url` to `out` (streamed to a temporary name beside it, renamed once it checks
// out as a video with frames), logging its size; otherwise nothing is left (it must not be
// ranked) and it fails with "the result of <s.job> (<out_rel>) is not a readable video: <why>",
// "<out_rel>: cannot write: No space left on device", or as HostedSession::download.
void download_candidate_video(HostedSession& s, const std::string& url,
                              const std::filesystem::path& out, const std::string& out_rel);

// The bytes of run_dir/recolored.png (the first frame); "<who>: <file>: cannot read ...".
std::string read_recolored_png(const std::filesystem::path& run_dir, const std::string& who);

// The prompt a generator is given: `prompt_template` with {prompt} = the user's prompt,
// trailing spaces and newlines dropped.
std::string video_prompt(const std::string& prompt_template, const std::string& prompt);

bool is_http_url(const std::string& url);  // an http:// or https:// URL (any case)

// Empties and recreates run_dir/candidates; fails with "<who>: <dir>: cannot ..." otherwise.
std::filesystem::path reset_candidates_dir(const std::filesystem::path& run_dir,
                                           const std::string& who);

}  // namespace svgm
