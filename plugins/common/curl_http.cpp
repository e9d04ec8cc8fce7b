// curl_http.h: the libcurl HttpTransport.
#include "common/curl_http.h"

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>

namespace svgm::plugin {

namespace {

// A chain of redirects longer than this is an error (curl's own default is 30; a storage
// redirect needs one or two).
constexpr int kMaxRedirects = 5;

struct Transfer {
  const std::function<bool()>* cancelled = nullptr;
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;
};

// One header line of the answer: "Name: value\r\n" (a new status line starts a new answer,
// e.g. after "100 Continue", so only the last answer's fields are kept).
size_t on_header(char* data, size_t size, size_t n, void* user) {
  try {
    auto* t = static_cast<Transfer*>(user);
    std::string line(data, size * n);
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    if (line.rfind("HTTP/", 0) == 0) {
      t->headers.clear();
      return size * n;
    }
    const size_t colon = line.find(':');
    if (colon == std::string::npos) return size * n;
    std::string name = line.substr(0, colon);
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    size_t v = colon + 1;
    while (v < line.size() && (line[v] == ' ' || line[v] == '\t')) ++v;
    t->headers.emplace_back(std::move(name), line.substr(v));
    return size * n;
  } catch (...) {
    return 0;
  }
}

size_t on_data(char* data, size_t size, size_t n, void* user) {
  try {
    static_cast<Transfer*>(user)->body.append(data, size * n);
    return size * n;
  } catch (...) {
    return 0;  // aborts the transfer
  }
}

int on_progress(void* user, curl_off_t, curl_off_t, curl_off_t, curl_off_t) {
  const auto* t = static_cast<Transfer*>(user);
  return t->cancelled && *t->cancelled && (*t->cancelled)() ? 1 : 0;
}

enum class Kind { get, json, file };

HttpReply perform(const std::function<bool()>& cancelled, const std::string& user_agent,
                  const std::vector<std::string>& extra_headers, Kind kind, const std::string& url,
                  const std::string& body, const std::string& field,
                  const std::filesystem::path& file, double timeout_s) {
  HttpReply reply;
  static const bool initialised = curl_global_init(CURL_GLOBAL_DEFAULT) == CURLE_OK;
  CURL* c = initialised ? curl_easy_init() : nullptr;
  if (!c) {
    reply.error = "libcurl failed to initialise";
    return reply;
  }
  Transfer t;
  t.cancelled = &cancelled;
  char err[CURL_ERROR_SIZE] = {0};
  const long timeout_ms = std::max(1L, std::lround(timeout_s * 1000));
  curl_slist* headers = nullptr;
  curl_mime* mime = nullptr;
  curl_easy_setopt(c, CURLOPT_URL, url.c_str());
  for (const auto& h : extra_headers) headers = curl_slist_append(headers, h.c_str());
  if (kind == Kind::json) {
    headers = curl_slist_append(headers, "Content-Type: application/json");
    curl_easy_setopt(c, CURLOPT_POST, 1L);
    curl_easy_setopt(c, CURLOPT_POSTFIELDS, body.data());
    curl_easy_setopt(c, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(body.size()));
  } else if (kind == Kind::file) {
    mime = curl_mime_init(c);
    curl_mimepart* part = curl_mime_addpart(mime);
    curl_mime_name(part, field.c_str());
    curl_mime_filedata(part, file.string().c_str());
    curl_mime_type(part, "image/png");
    curl_mimepart* overwrite = curl_mime_addpart(mime);
    curl_mime_name(overwrite, "overwrite");
    curl_mime_data(overwrite, "true", CURL_ZERO_TERMINATED);
    curl_easy_setopt(c, CURLOPT_MIMEPOST, mime);
  }
  if (headers) curl_easy_setopt(c, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(c, CURLOPT_HEADERFUNCTION, on_header);
  curl_easy_setopt(c, CURLOPT_HEADERDATA, &t);
  curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, on_data);
  curl_easy_setopt(c, CURLOPT_WRITEDATA, &t);
  curl_easy_setopt(c, CURLOPT_NOPROGRESS, 0L);
  curl_easy_setopt(c, CURLOPT_XFERINFOFUNCTION, on_progress);
  curl_easy_setopt(c, CURLOPT_XFERINFODATA, &t);
  curl_easy_setopt(c, CURLOPT_TIMEOUT_MS, timeout_ms);
  curl_easy_setopt(c, CURLOPT_CONNECTTIMEOUT_MS, timeout_ms);
  curl_easy_setopt(c, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(c, CURLOPT_ERRORBUFFER, err);
  curl_easy_setopt(c, CURLOPT_USERAGENT, user_agent.c_str());
  const CURLcode rc = curl_easy_perform(c);
  long status = 0;
  curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, &status);
  if (rc == CURLE_OK && status >= 300 && status < 400) {
    char* location = nullptr;  // absolute, resolved against `url` by curl
    if (curl_easy_getinfo(c, CURLINFO_REDIRECT_URL, &location) == CURLE_OK && location)
      t.headers.emplace_back("location", location);
  }
  curl_slist_free_all(headers);
  curl_mime_free(mime);
  curl_easy_cleanup(c);
  if (rc == CURLE_OK) {
    reply.connected = true;
    reply.status = status;
    reply.body = std::move(t.body);
    reply.headers = std::move(t.headers);
  } else {
    reply.timed_out = rc == CURLE_OPERATION_TIMEDOUT;
    reply.error = *err ? err : curl_easy_strerror(rc);
  }
  return reply;
}

}  // namespace

std::string url_origin(const std::string& url) {
  const size_t scheme = url.find("://");
  if (scheme == std::string::npos) return "";
  std::string origin = url.substr(0, url.find_first_of("/?#", scheme + 3));
  for (char& c : origin) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return origin;
}

CurlTransport::CurlTransport(std::function<bool()> cancelled, std::string user_agent,
                             std::vector<std::string> headers, ScopedHeaders secret)
    : cancelled_(std::move(cancelled)), user_agent_(std::move(user_agent)), headers_(std::move(headers)),
      secret_(std::move(secret)) {
  secret_.origin = url_origin(secret_.origin);  // normalised: "" (no secret) stays ""
}

std::vector<std::string> CurlTransport::headers_for(const std::string& url) const {
  std::vector<std::string> h = headers_;
  if (!secret_.origin.empty() && url_origin(url) == secret_.origin)
    h.insert(h.end(), secret_.headers.begin(), secret_.headers.end());
  return h;
}

// Follows redirects itself (not CURLOPT_FOLLOWLOCATION) so the secret headers are chosen again
// for every hop's origin; the time limit covers the whole chain.
HttpReply CurlTransport::get(const std::string& url_in, double timeout_s) {
  using Clock = std::chrono::steady_clock;
  const auto end = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  std::string url = url_in;
  for (int hop = 0;; ++hop) {
    const double left = std::chrono::duration<double>(end - Clock::now()).count();
    if (left <= 0) {
      HttpReply r;
      r.timed_out = true;
      r.error = "timed out following redirects";
      return r;
    }
    HttpReply r = perform(cancelled_, user_agent_, headers_for(url), Kind::get, url, {}, {}, {}, left);
    const std::string location = r.header("location");
    if (!r.connected || r.status < 300 || r.status >= 400 || location.empty()) return r;
    if (hop >= kMaxRedirects) {
      r.connected = false;
      r.error = "more than " + std::to_string(kMaxRedirects) + " redirects";
      return r;
    }
    url = location;
  }
}

HttpReply CurlTransport::post_json(const std::string& url, const std::string& body,
                                   double timeout_s) {
  return perform(cancelled_, user_agent_, headers_for(url), Kind::json, url, body, {}, {}, timeout_s);
}

HttpReply CurlTransport::post_file(const std::string& url, const std::string& field,
                                   const std::filesystem::path& file, double timeout_s) {
  return perform(cancelled_, user_agent_, headers_for(url), Kind::file, url, {}, field, file, timeout_s);
}

}  // namespace svgm::plugin
