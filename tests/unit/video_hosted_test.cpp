// The hosted video clients (Veo through the Gemini API, the configurable http-job client) and
// what they share (hosted_session, candidate_pool), driven through a fake HttpTransport that
// answers in the documented shapes: request bodies, polling, 429 with Retry-After, a refused
// key (never shown), a failed candidate among good ones, a result that is not a video, time
// limits, and at most `concurrency` candidates in flight.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "media/preview_video.h"
#include "net/base64.h"
#include "svgmotion/error.h"
#include "svgmotion/png_io.h"
#include "generators/hosted_session.h"
#include "generators/http_job_client.h"
#include "generators/veo_client.h"

#include "error_of.h"
#include "temp_dir.h"

using namespace svgm;
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const char* const kKey = "AIza-test-SECRET-4242";
const char* const kBase = "https://api.test/v1beta";

struct Request {
  std::string method, url, body;
};

// Answers with `handler`; records every request. Safe from several threads (the pool's).
struct FakeHttp : HttpTransport {
  std::function<HttpReply(const Request&)> handler;
  std::mutex m;
  std::vector<Request> requests;
  HttpReply serve(Request r) {
    {
      std::lock_guard<std::mutex> lock(m);
      requests.push_back(r);
    }
    return handler(r);
  }
  HttpReply get(const std::string& url, double) override { return serve({"GET", url, ""}); }
  HttpReply post_json(const std::string& url, const std::string& body, double) override {
    return serve({"POST", url, body});
  }
  HttpReply post_file(const std::string& url, const std::string&, const fs::path&, double) override {
    return serve({"FILE", url, ""});
  }
  std::vector<Request> of(const std::string& method) {
    std::lock_guard<std::mutex> lock(m);
    std::vector<Request> out;
    for (const auto& r : requests)
      if (r.method == method) out.push_back(r);
    return out;
  }
};

HttpReply answer(long status, const std::string& body, std::vector<std::pair<std::string, std::string>> headers = {}) {
  HttpReply r;
  r.connected = true;
  r.status = status;
  r.body = body;
  r.headers = std::move(headers);
  return r;
}

std::string read_file(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

RgbaImage solid(int w, int h, uint8_t r) {
  RgbaImage im;
  im.width = w;
  im.height = h;
  im.rgba.assign(static_cast<size_t>(w) * h * 4, 255);
  for (size_t i = 0; i < im.rgba.size(); i += 4) im.rgba[i + 1] = r;
  return im;
}

// A run directory with recolored.png, and the bytes of a small real mp4 to serve.
struct RunDir {
  test::TempDir tmp{"svgm_hosted_test"};
  fs::path run;
  std::string png, video;
  RunDir() {
    run = tmp.path / "run";
    fs::create_directories(run);
    write_png(run / "recolored.png", solid(16, 16, 30));
    png = read_file(run / "recolored.png");
    const fs::path v = tmp.path / "served.mp4";
    write_preview_video(v, 5, 1, [](int k, int) { return solid(32, 32, static_cast<uint8_t>(50 * k)); }, 24);
    video = read_file(v);
  }
};

using test::error_of;

// Test options: fast polls, no real pauses.
VeoOptions fast_veo(int candidates) {
  VeoOptions o = parse_veo_options(json{{"base_url", kBase}, {"candidates", candidates}, {"poll_s", 0.01},
                                        {"poll_max_s", 0.02}, {"retries", 2}, {"timeout_s", 30}});
  return o;
}

// A Gemini-API-shaped server: operation opN is done on its `polls_needed`-th poll; `fail_seed`
// makes that seed's operation end with an error. Tracks operations in flight (submitted, not
// yet downloaded).
struct FakeVeo {
  FakeHttp http;
  std::mutex m;
  int next_op = 0, in_flight = 0, max_in_flight = 0;
  std::map<std::string, int> polls;
  std::map<std::string, int64_t> seed_of;
  int polls_needed = 2;
  int64_t fail_seed = -1;
  std::string video;
  explicit FakeVeo(std::string bytes) : video(std::move(bytes)) {
    http.handler = [this](const Request& r) { return serve(r); };
  }
  HttpReply serve(const Request& r) {
    std::lock_guard<std::mutex> lock(m);
    const std::string op_prefix = std::string(kBase) + "/models/veo-3.1-generate-preview/operations/";
    if (r.method == "POST") {
      const json b = json::parse(r.body);
      const std::string name = "models/veo-3.1-generate-preview/operations/op" + std::to_string(next_op++);
      seed_of[name] = b["parameters"].value("seed", int64_t{-2});
      ++in_flight;
      max_in_flight = std::max(max_in_flight, in_flight);
      return answer(200, json{{"name", name}}.dump());
    }
    if (r.url.rfind(op_prefix, 0) == 0) {
      const std::string name = r.url.substr(std::string(kBase).size() + 1);
      if (++polls[name] < polls_needed) return answer(200, json{{"name", name}, {"done", false}}.dump());
      if (seed_of[name] == fail_seed) {
        --in_flight;
        return answer(200, json{{"name", name}, {"done", true}, {"error", {{"code", 13}, {"message", "internal: boom"}}}}.dump());
      }
      const std::string id = name.substr(name.rfind('/') + 1);
      return answer(200, json{{"name", name},
                              {"done", true},
                              {"response",
                               {{"@type", "type.googleapis.com/google.ai.generativelanguage.v1beta.PredictLongRunningResponse"},
                                {"generateVideoResponse",
                                 {{"generatedSamples",
                                   json::array({{{"video", {{"uri", std::string(kBase) + "/files/" + id + ":download?alt=media"}}}}})}}}}}}
                             .dump());
    }
    if (r.url.find("/files/") != std::string::npos) {
      --in_flight;
      return answer(200, video);
    }
    return answer(404, R"({"error": {"code": 404, "message": "no such thing"}})");
  }
};

}  // namespace

TEST_SUITE("video") {

TEST_CASE("the Veo request carries the image, the prompt and the parameters the API takes") {
  VeoOptions o = parse_veo_options(json::object());
  CHECK(o.model == "veo-3.1-generate-preview");
  CHECK(o.api_key_env == "GEMINI_API_KEY");
  const json r = veo_request(o, "abc", "a bird flies", 7);
  CHECK(r["instances"].size() == 1);
  CHECK(r["instances"][0]["prompt"] == "a bird flies");
  CHECK(r["instances"][0]["image"]["bytesBase64Encoded"] == "YWJj");  // base64("abc"), by hand
  CHECK(r["instances"][0]["image"]["mimeType"] == "image/png");
  CHECK(r["parameters"] == json{{"aspectRatio", "16:9"}, {"durationSeconds", 8}, {"resolution", "720p"}, {"seed", 7}});
  o = parse_veo_options(json{{"aspect_ratio", ""}, {"duration_s", 0}, {"resolution", ""}, {"seed", false},
                             {"negative_prompt", "shading"}});
  CHECK(veo_request(o, "", "p", 1)["parameters"] == json{{"negativePrompt", "shading"}});
  CHECK(error_of([] { parse_veo_options(json{{"modle", "x"}}); }).rfind("video veo: unknown option 'modle'", 0) == 0);
  CHECK(error_of([] { parse_veo_options(json{{"seed", 3}}); }) == "video veo: options.seed must be true or false, not 3");
  CHECK(error_of([] { parse_veo_options(json{{"base_url", "ftp://x"}}); }) ==
        "video veo: options.base_url must start with http:// or https://, not ftp://x");
}

TEST_CASE("a Veo operation is read as pending, a video, an error or a filtered result") {
  CHECK_FALSE(read_veo_operation(json{{"name", "x"}}).done);
  CHECK_FALSE(read_veo_operation(json{{"name", "x"}, {"done", false}}).done);
  const VeoOperation ok = read_veo_operation(json::parse(
      R"({"done": true, "response": {"generateVideoResponse": {"generatedSamples": [{"video": {"uri": "https://h/v"}}]}}})"));
  CHECK(ok.done);
  CHECK(ok.video_uri == "https://h/v");
  CHECK(ok.error.empty());
  CHECK(read_veo_operation(json::parse(R"({"done": true, "error": {"code": 8, "message": "quota"}})")).error ==
        "quota (code 8)");
  CHECK(read_veo_operation(json::parse(
                               R"({"done": true, "response": {"generateVideoResponse": {"raiMediaFilteredCount": 1, "raiMediaFilteredReasons": ["r1"]}}})"))
            .error == "the video was filtered: r1");
}

TEST_CASE("Veo: candidates in parallel within the concurrency, polled until done, saved as videos") {
  RunDir d;
  FakeVeo veo(d.video);
  VeoOptions o = fast_veo(3);
  o.concurrency = 2;
  veo.polls_needed = 3;
  std::vector<std::string> logs;
  HostedHooks hooks;
  hooks.log = [&](const std::string& l) { logs.push_back(l); };
  const auto files = generate_veo_candidates(o, d.run, "waves", 5, {kKey, "GEMINI_API_KEY"}, veo.http, hooks);
  REQUIRE(files.size() == 3);
  for (int i = 0; i < 3; ++i) {
    CHECK(files[static_cast<size_t>(i)] == d.run / "candidates" / ("0" + std::to_string(i) + ".mp4"));
    CHECK(read_file(files[static_cast<size_t>(i)]) == d.video);
  }
  const auto posts = veo.http.of("POST");
  REQUIRE(posts.size() == 3);
  std::vector<int64_t> seeds;
  for (const auto& p : posts) {
    CHECK(p.url == std::string(kBase) + "/models/veo-3.1-generate-preview:predictLongRunning");
    const json b = json::parse(p.body);
    seeds.push_back(b["parameters"]["seed"].get<int64_t>());
    CHECK(b["instances"][0]["image"]["bytesBase64Encoded"] == base64(d.png));
    const std::string prompt = b["instances"][0]["prompt"];
    CHECK(prompt.rfind("A flat 2D vector", 0) == 0);
    CHECK(prompt.substr(prompt.size() - 5) == "waves");
  }
  std::sort(seeds.begin(), seeds.end());
  CHECK(seeds == std::vector<int64_t>{5, 6, 7});
  CHECK(veo.max_in_flight == 2);  // two at once, never three
  CHECK(veo.http.of("GET").size() == 3 * 3 + 3);  // three polls and one download each
  CHECK(std::count_if(logs.begin(), logs.end(), [](const std::string& l) { return l.find("submitted as operation") != std::string::npos; }) == 3);
}

TEST_CASE("Veo: a rate limit waits as long as Retry-After says, then goes on") {
  RunDir d;
  FakeVeo veo(d.video);
  std::atomic<int> refused{0};
  std::vector<std::chrono::steady_clock::time_point> submits;
  auto serve = veo.http.handler;
  veo.http.handler = [&](const Request& r) {
    if (r.method == "POST") submits.push_back(std::chrono::steady_clock::now());  // one candidate: one thread
    if (r.method == "POST" && refused++ == 0)
      return answer(429, R"({"error": {"code": 429, "message": "Resource has been exhausted", "status": "RESOURCE_EXHAUSTED"}})",
                    {{"retry-after", "1"}});
    return serve(r);
  };
  std::vector<std::string> logs;
  HostedHooks hooks;
  hooks.log = [&](const std::string& l) { logs.push_back(l); };
  const auto files = generate_veo_candidates(fast_veo(1), d.run, "waves", 0, {kKey, "GEMINI_API_KEY"}, veo.http, hooks);
  CHECK(files.size() == 1);
  REQUIRE(submits.size() == 2);
  // The 1 s asked, not the 0.5 s of the first backoff (the pause ends by the steady clock).
  CHECK(std::chrono::duration<double>(submits[1] - submits[0]).count() >= 1.0);
  REQUIRE_FALSE(logs.empty());
  CHECK(logs[0] == "video veo: candidate 00: HTTP 429 from " + std::string(kBase) +
                       "/models/veo-3.1-generate-preview:predictLongRunning: Resource has been exhausted; retrying in 1 s");
}

TEST_CASE("Veo: a Retry-After past the deadline fails at once, naming it") {
  RunDir d;
  FakeVeo veo(d.video);
  veo.http.handler = [](const Request&) { return answer(429, "{}", {{"retry-after", "120"}}); };
  VeoOptions o = fast_veo(1);
  o.limits.timeout_s = 5;
  CHECK(error_of([&] { generate_veo_candidates(o, d.run, "w", 0, {kKey, "GEMINI_API_KEY"}, veo.http); }) ==
        "video veo: candidate 00: HTTP 429 from " + std::string(kBase) +
            "/models/veo-3.1-generate-preview:predictLongRunning: {}; the server asks to retry after 120 s, past the "
            "candidate's time limit of 5 s");
}

TEST_CASE("Veo: a refused key is one line naming the variable, never the key, and is not retried") {
  RunDir d;
  FakeHttp http;
  // A hostile variant of Google's answer that echoes the key back.
  http.handler = [](const Request&) {
    return answer(400, json{{"error", {{"code", 400}, {"message", std::string("API key not valid: ") + kKey},
                                       {"status", "INVALID_ARGUMENT"},
                                       {"details", json::array({{{"reason", "API_KEY_INVALID"}}})}}}}
                           .dump());
  };
  const std::string e =
      error_of([&] { generate_veo_candidates(fast_veo(1), d.run, "w", 0, {kKey, "GEMINI_API_KEY"}, http); });
  CHECK(e == "video veo: candidate 00: the API key in $GEMINI_API_KEY was refused: HTTP 400 from " +
                 std::string(kBase) + "/models/veo-3.1-generate-preview:predictLongRunning: API key not valid: <key>");
  CHECK(e.find(kKey) == std::string::npos);
  CHECK(http.requests.size() == 1);
}

TEST_CASE("Veo: one failed candidate leaves the others, with one warning naming it") {
  RunDir d;
  FakeVeo veo(d.video);
  veo.fail_seed = 11;  // candidate 01 of seed 10
  std::vector<std::string> warnings;
  HostedHooks hooks;
  hooks.warn = [&](const std::string& l) { warnings.push_back(l); };
  const auto files = generate_veo_candidates(fast_veo(3), d.run, "w", 10, {kKey, "GEMINI_API_KEY"}, veo.http, hooks);
  REQUIRE(files.size() == 2);
  CHECK(files[0].filename() == "00.mp4");
  CHECK(files[1].filename() == "02.mp4");
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].rfind("video veo: candidate 01: operation models/veo-3.1-generate-preview/operations/op", 0) == 0);
  CHECK(warnings[0].find(" failed: internal: boom (code 13)") != std::string::npos);
  CHECK_FALSE(fs::exists(d.run / "candidates" / "01.mp4"));
}

TEST_CASE("Veo: every candidate failing is an error; a result that is not a video is not kept") {
  RunDir d;
  FakeVeo veo("<html>not a video</html>");
  std::vector<std::string> warnings;
  HostedHooks hooks;
  hooks.warn = [&](const std::string& l) { warnings.push_back(l); };
  const std::string e =
      error_of([&] { generate_veo_candidates(fast_veo(2), d.run, "w", 0, {kKey, "GEMINI_API_KEY"}, veo.http, hooks); });
  CHECK(e.rfind("video veo: all 2 candidates failed (the first: video veo: candidate 00: the result of operation ", 0) == 0);
  CHECK(e.find("(candidates/00.mp4) is not a readable video") != std::string::npos);
  CHECK(warnings.size() == 2);
  CHECK(fs::is_empty(d.run / "candidates"));
}

TEST_CASE("Veo: an operation that never finishes stops at the candidate's time limit") {
  RunDir d;
  FakeVeo veo(d.video);
  veo.polls_needed = 1 << 30;
  VeoOptions o = fast_veo(1);
  o.limits.timeout_s = 0.3;
  CHECK(error_of([&] { generate_veo_candidates(o, d.run, "w", 0, {kKey, "GEMINI_API_KEY"}, veo.http); }) ==
        "video veo: candidate 00: no result within 0.3 s (operation models/veo-3.1-generate-preview/operations/op0)");
}

TEST_CASE("http-job: field paths, body and URL templates, and the key only in headers") {
  const json j = json::parse(R"({"a": {"b": [ "x", {"c": 3} ]}, "s": "t"})");
  CHECK(field_at(j, "a.b.0") == "x");
  CHECK(field_at(j, "a.b.1.c") == 3);
  CHECK(field_at(j, "a.b.2").is_null());
  CHECK(field_at(j, "s") == "t");
  CHECK(field_at(j, "nope.x").is_null());

  const json body = json::parse(R"({"input": {"prompt": "say {prompt}!", "image": "{image_data_url}", "raw": "{image_base64}",
                                    "seed": "{seed}", "num_frames": "{frames}", "fps": "{fps}", "keep": [1, "{other}"]}})");
  const json filled = fill_job_body(body, "waves", "abc", 42, 81, 16);
  CHECK(filled["input"]["prompt"] == "say waves!");
  CHECK(filled["input"]["image"] == "data:image/png;base64,YWJj");
  CHECK(filled["input"]["raw"] == "YWJj");
  CHECK(filled["input"]["seed"] == 42);
  CHECK(filled["input"]["num_frames"] == 81);
  CHECK(filled["input"]["fps"] == 16.0);
  CHECK(filled["input"]["keep"] == json::array({1, "{other}"}));

  const json reply = json::parse(R"({"id": "p1", "urls": {"get": "https://h/p/p1"}})");
  CHECK(fill_job_url("{submit.urls.get}", reply, "") == "https://h/p/p1");
  CHECK(fill_job_url("https://h/q/{id}/status?x={y}", reply, "id") == "https://h/q/p1/status?x={y}");
  CHECK(error_of([&] { fill_job_url("{submit.status_url}", reply, ""); }) ==
        "video http-job: the submit reply has no field status_url for {submit.status_url}: " + reply.dump());

  const json base = {{"submit_url", "https://h/submit"}, {"body", {{"p", "{prompt}"}}}, {"status_url", "{submit.s}"},
                     {"done_values", {"DONE"}}, {"video_url_field", "video.url"}};
  json o = base;
  o["headers"] = {{"Authorization", "Key {api_key}"}};
  o["api_key_env"] = "FAL_KEY";
  CHECK(job_headers(parse_http_job_options(o), "k1") == std::vector<std::string>{"Authorization: Key k1"});
  o["body"]["p"] = "{api_key}";
  CHECK(error_of([&] { parse_http_job_options(o); }) == "video http-job: {api_key} may only appear in options.headers");
  o = base;
  o["headers"] = {{"Authorization", "Key {api_key}"}};
  CHECK(error_of([&] { parse_http_job_options(o); }) ==
        "video http-job: options.headers use {api_key} but options.api_key_env is not set");
  o = base;
  o.erase("done_values");
  CHECK(error_of([&] { parse_http_job_options(o); }) ==
        "video http-job: options.done_values is not set (the status values of a finished job)");
}

TEST_CASE("http-job: a queue API (submit, status, result URLs from the reply) and a failed job") {
  RunDir d;
  FakeHttp http;
  std::mutex m;
  std::map<std::string, int> polls;
  // fal.ai's queue shape: IN_QUEUE, IN_PROGRESS, COMPLETED; the result at response_url. The job
  // of seed 2 fails in Replicate's way instead (status "FAILED", an error message).
  http.handler = [&](const Request& r) {
    std::lock_guard<std::mutex> lock(m);
    if (r.method == "POST") {
      const json b = json::parse(r.body);
      const std::string id = "req" + std::to_string(b["seed"].get<int>());
      return answer(200, json{{"request_id", id}, {"status_url", "https://q.test/requests/" + id + "/status"},
                              {"response_url", "https://q.test/requests/" + id}}
                             .dump());
    }
    if (r.url.find("/status") != std::string::npos) {
      const size_t at = r.url.find("/requests/") + 10;
      const std::string id = r.url.substr(at, r.url.find("/status") - at);
      const int n = ++polls[id];
      if (id == "req2" && n == 2) return answer(200, R"({"status": "FAILED", "error": "out of memory"})");
      return answer(200, json{{"status", n == 1 ? "IN_QUEUE" : n == 2 ? "IN_PROGRESS" : "COMPLETED"}}.dump());
    }
    if (r.url.find("/requests/") != std::string::npos)
      return answer(200, json{{"video", {{"url", "https://cdn.test/" + r.url.substr(r.url.rfind('/') + 1) + ".webm?sig=1"}}}}.dump());
    if (r.url.rfind("https://cdn.test/", 0) == 0) return answer(200, d.video);
    return answer(404, "{}");
  };
  const HttpJobOptions o = parse_http_job_options(json::parse(R"({
      "submit_url": "https://q.test/fal-ai/wan-i2v", "body": {"prompt": "{prompt}", "image_url": "{image_data_url}", "seed": "{seed}"},
      "id_field": "request_id", "status_url": "{submit.status_url}", "result_url": "{submit.response_url}",
      "done_values": ["COMPLETED"], "failed_values": ["FAILED"], "video_url_field": "video.url",
      "candidates": 3, "concurrency": 3, "poll_s": 0.01, "poll_max_s": 0.01, "timeout_s": 30})"));
  std::vector<std::string> warnings;
  HostedHooks hooks;
  hooks.warn = [&](const std::string& l) { warnings.push_back(l); };
  const auto files = generate_http_job_candidates(o, d.run, "waves", 0, {}, http, hooks);
  REQUIRE(files.size() == 2);
  CHECK(files[0] == d.run / "candidates" / "00.webm");  // the URL's extension, its query dropped
  CHECK(files[1] == d.run / "candidates" / "01.webm");
  CHECK(read_file(files[1]) == d.video);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == "video http-job: candidate 02: job req2 failed (status FAILED): out of memory");
  const auto posts = http.of("POST");
  REQUIRE(posts.size() == 3);
  const json b = json::parse(posts[0].body);
  CHECK(b["image_url"] == "data:image/png;base64," + base64(d.png));
  CHECK(polls["req0"] == 3);
}

// The hostile server of the security issue, through the session every client shares.
HttpJobOptions hostile_job(int retries = 0) {
  return parse_http_job_options(json{{"submit_url", "https://q.test/submit"}, {"body", {{"p", "{prompt}"}}},
                                     {"headers", {{"Authorization", "Bearer {api_key}"}}}, {"api_key_env", "K"},
                                     {"status_url", "{submit.status_url}"}, {"done_values", {"done"}},
                                     {"video_url_field", "video_url"}, {"candidates", 1}, {"retries", retries},
                                     {"poll_s", 0.01}, {"poll_max_s", 0.01}, {"timeout_s", 30}});
}

TEST_CASE("hosted: a key echoed across the excerpt's cut leaves no 8-character piece on any message") {
  RunDir d;
  FakeHttp http;
  const std::string key = "sk-live/Ab+Cd=Ef:Gh.Ij_Kl-Mn0123456789opqrstuv";
  http.handler = [&](const Request&) {
    return answer(500, json{{"detail", std::string(190, 'x') + key + " is not a key we know"}}.dump());
  };
  std::vector<std::string> logs;
  HostedHooks hooks;
  hooks.log = [&](const std::string& l) { logs.push_back(l); };
  const std::string e =
      error_of([&] { generate_http_job_candidates(hostile_job(1), d.run, "w", 0, {key, "K"}, http, hooks); });
  CHECK(e == "video http-job: candidate 00: HTTP 500 from https://q.test/submit: " + std::string(190, 'x') + "<key> is n...");
  REQUIRE(logs.size() == 1);  // the retry
  CHECK(logs[0].find("<key> is n...; retrying in") != std::string::npos);
  for (const std::string& text : {e, logs[0]})
    for (size_t i = 0; i + 8 <= key.size(); ++i) CHECK(text.find(key.substr(i, 8)) == std::string::npos);
}

TEST_CASE("hosted: a status_url that is not http(s) is refused, naming its scheme only, and never fetched") {
  RunDir d;
  FakeHttp http;
  http.handler = [&](const Request& r) {
    if (r.method == "POST") return answer(200, R"({"status": "queued", "status_url": "file:///etc/passwd?token=t0p"})");
    return answer(200, "root:x:0:0:root:/root:/bin/bash");
  };
  CHECK(error_of([&] { generate_http_job_candidates(hostile_job(), d.run, "w", 0, {}, http); }) ==
        "video http-job: candidate 00: refused to fetch a file: URL (only http and https)");
  CHECK(http.of("GET").empty());
}

TEST_CASE("hosted: a refusal by the transport (size limit, scheme) is one line and not retried") {
  RunDir d;
  FakeHttp http;
  http.handler = [&](const Request& r) {
    if (r.method == "POST") return answer(200, R"({"status": "queued", "status_url": "https://q.test/s"})");
    HttpReply big;
    big.refused = true;
    big.error = too_large_message("reply", r.url, kMaxReplyBytes);
    return big;
  };
  CHECK(error_of([&] { generate_http_job_candidates(hostile_job(3), d.run, "w", 0, {}, http); }) ==
        "video http-job: candidate 00: the reply from q.test is larger than 16 MiB");
  CHECK(http.of("GET").size() == 1);
}

TEST_CASE("hosted: a video over max_video_mib is cut off; a download the disk refuses names the file") {
  RunDir d;
  // Through the default download (get, then write): a body of 1 MiB and a byte.
  FakeHttp http;
  http.handler = [&](const Request& r) {
    if (r.method == "POST")
      return answer(200, R"({"status": "done", "status_url": "https://q.test/s", "video_url": "https://cdn.test/v.mp4"})");
    return answer(200, std::string((size_t{1} << 20) + 1, 'v'));
  };
  HttpJobOptions opts = parse_http_job_options(json{{"submit_url", "https://q.test/submit"}, {"body", json::object()},
                                                     {"status_url", "{submit.status_url}"}, {"done_values", {"done"}},
                                                     {"video_url_field", "video_url"}, {"candidates", 1},
                                                     {"retries", 2}, {"max_video_mib", 1}});
  CHECK(error_of([&] { generate_http_job_candidates(opts, d.run, "w", 0, {}, http); }) ==
        "video http-job: candidate 00: the download from cdn.test is larger than 1 MiB");
  CHECK(http.of("GET").size() == 1);
  CHECK(fs::is_empty(d.run / "candidates"));

  // An injected writer that fails as a full disk does.
  struct FullDisk : FakeHttp {
    HttpReply download(const std::string& url, const fs::path& file, uint64_t, double) override {
      serve({"GET", url, ""});
      std::ofstream(file) << "part";  // what was written before the disk filled
      HttpReply r = answer(200, "");
      r.write_error = "No space left on device";
      return r;
    }
  } full;
  full.handler = http.handler;
  CHECK(error_of([&] { generate_http_job_candidates(opts, d.run, "w", 0, {}, full); }) ==
        "video http-job: candidate 00: candidates/00.mp4: cannot write: No space left on device");
  CHECK(full.of("GET").size() == 1);  // not retried
  CHECK(fs::is_empty(d.run / "candidates"));  // nor left half-written
}

}  // TEST_SUITE
