// curl_http.h: the libcurl HttpTransport.
#include "common/curl_http.h"

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>

namespace svgm::plugin {

namespace {

// A chain of redirects longer than this is an error (curl's own default is 30; a storage
// redirect needs one or two).
constexpr int kMaxRedirects = 5;

// The only protocols fetched or followed (curl's list syntax).
const char* const kProtocols = "http,https";

bool is_http(const std::string& url) {
  const std::string s = url_scheme(url);
  return s == "http" || s == "https";
}

// Where a body goes: into `body` up to max_body bytes, or (a 2xx answer to download()) into
// `file` up to max_file bytes. Past a limit, or when the file cannot be written, the callback
// returns 0 and curl aborts the transfer.
struct Transfer {
  const std::function<bool()>* cancelled = nullptr;
  CURL* curl = nullptr;
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;
  uint64_t max_body = kMaxReplyBytes;
  std::FILE* file = nullptr;
  uint64_t max_file = 0, written = 0;
  uint64_t exceeded = 0;  // the limit that was passed, 0 = none
  int write_errno = 0;
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
    auto* t = static_cast<Transfer*>(user);
    const size_t bytes = size * n;
    long status = 0;
    if (t->file) curl_easy_getinfo(t->curl, CURLINFO_RESPONSE_CODE, &status);
    if (t->file && status >= 200 && status < 300) {
      if (t->written + bytes > t->max_file) {
        t->exceeded = t->max_file;
        return 0;
      }
      errno = 0;
      if (std::fwrite(data, 1, bytes, t->file) != bytes) {
        t->write_errno = errno ? errno : EIO;
        return 0;
      }
      t->written += bytes;
      return bytes;
    }
    if (t->body.size() + bytes > t->max_body) {
      t->exceeded = t->max_body;
      return 0;
    }
    t->body.append(data, bytes);
    return bytes;
  } catch (...) {
    return 0;  // aborts the transfer
  }
}

int on_progress(void* user, curl_off_t, curl_off_t, curl_off_t, curl_off_t) {
  const auto* t = static_cast<Transfer*>(user);
  return t->cancelled && *t->cancelled && (*t->cancelled)() ? 1 : 0;
}

enum class Kind { get, json, file };

HttpReply refusal(const std::string& why) {
  HttpReply r;
  r.refused = true;
  r.error = why;
  return r;
}

// One exchange, no redirect followed. `out` (may be null): where a 2xx body goes, up to
// max_file bytes (see Transfer).
HttpReply perform(const std::function<bool()>& cancelled, const std::string& user_agent,
                  const std::vector<std::string>& extra_headers, Kind kind, const std::string& url,
                  const std::string& body, const std::string& field,
                  const std::filesystem::path& file, double timeout_s, std::FILE* out = nullptr,
                  uint64_t max_file = 0) {
  if (!is_http(url)) return refusal("refused to fetch " + scheme_for_message(url) + " (only http and https)");
  HttpReply reply;
  static const bool initialised = curl_global_init(CURL_GLOBAL_DEFAULT) == CURLE_OK;
  CURL* c = initialised ? curl_easy_init() : nullptr;
  if (!c) {
    reply.error = "libcurl failed to initialise";
    return reply;
  }
  Transfer t;
  t.cancelled = &cancelled;
  t.curl = c;
  t.file = out;
  t.max_file = max_file;
  char err[CURL_ERROR_SIZE] = {0};
  const long timeout_ms = std::max(1L, std::lround(timeout_s * 1000));
  curl_slist* headers = nullptr;
  curl_mime* mime = nullptr;
  curl_easy_setopt(c, CURLOPT_URL, url.c_str());
  // Belt and braces with is_http above and the Location check in get_to: libcurl itself will
  // speak nothing else, even if a later change turned on its own redirect following.
  curl_easy_setopt(c, CURLOPT_PROTOCOLS_STR, kProtocols);
  curl_easy_setopt(c, CURLOPT_REDIR_PROTOCOLS_STR, kProtocols);
  // An announced Content-Length over the limit aborts before the body starts.
  curl_easy_setopt(c, CURLOPT_MAXFILESIZE_LARGE, static_cast<curl_off_t>(out ? std::max(max_file, t.max_body) : t.max_body));
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
  curl_slist_free_all(headers);
  curl_mime_free(mime);
  curl_easy_cleanup(c);
  if (t.write_errno) {
    reply.write_error = std::strerror(t.write_errno);
    reply.error = "cannot write the body: " + reply.write_error;
  } else if (t.exceeded || rc == CURLE_FILESIZE_EXCEEDED) {
    const bool to_file = out && status >= 200 && status < 300;
    return refusal(too_large_message(to_file ? "download" : "reply", url, to_file ? max_file : t.max_body));
  } else if (rc == CURLE_OK) {
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

std::string resolve_location(const std::string& base, const std::string& location) {
  CURLU* u = curl_url();
  std::string out;
  char* resolved = nullptr;
  // CURLU_NON_SUPPORT_SCHEME: a Location in a scheme this libcurl lacks still parses, so the
  // refusal can name it.
  if (u && curl_url_set(u, CURLUPART_URL, base.c_str(), 0) == CURLUE_OK &&
      curl_url_set(u, CURLUPART_URL, location.c_str(), CURLU_NON_SUPPORT_SCHEME) == CURLUE_OK &&
      curl_url_get(u, CURLUPART_URL, &resolved, 0) == CURLUE_OK && resolved)
    out = resolved;
  curl_free(resolved);
  curl_url_cleanup(u);
  return out;
}

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
// for every hop's origin and every Location is checked (http or https only) and resolved here;
// the time limit covers the whole chain.
HttpReply CurlTransport::get_to(const std::string& url_in, std::FILE* file, uint64_t max_file, double timeout_s) {
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
    HttpReply r = perform(cancelled_, user_agent_, headers_for(url), Kind::get, url, {}, {}, {}, left, file, max_file);
    const std::string location = r.header("location");
    if (!r.connected || r.status < 300 || r.status >= 400 || location.empty()) return r;
    if (hop >= kMaxRedirects) {
      r.connected = false;
      r.error = "more than " + std::to_string(kMaxRedirects) + " redirects";
      return r;
    }
    // The scheme is named from the Location as sent, before resolving, so that one libcurl
    // cannot parse ("javascript:...") is still refused by name.
    const std::string raw_scheme = url_scheme(location);
    const std::string next = resolve_location(url, location);
    if ((!raw_scheme.empty() && raw_scheme != "http" && raw_scheme != "https") || (!next.empty() && !is_http(next)))
      return refusal(url_host(url) + " redirected to " + scheme_for_message(raw_scheme.empty() ? next : location) +
                     " (only http and https are followed)");
    if (next.empty()) return refusal(url_host(url) + " sent a redirect whose Location is not a URL");
    url = next;
  }
}

HttpReply CurlTransport::get(const std::string& url, double timeout_s) { return get_to(url, nullptr, 0, timeout_s); }

HttpReply CurlTransport::download(const std::string& url, const std::filesystem::path& file, uint64_t max_bytes,
                                  double timeout_s) {
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (!f) {
    HttpReply r;
    r.write_error = std::strerror(errno);
    r.error = "cannot create " + file.string() + ": " + r.write_error;
    return r;
  }
  HttpReply r = get_to(url, f, max_bytes, timeout_s);
  // A full disk may show only when the buffered tail is written out.
  if (std::fclose(f) != 0 && r.write_error.empty() && r.connected && r.status >= 200 && r.status < 300) {
    r.write_error = std::strerror(errno);
    r.connected = false;
    r.error = "cannot write the body: " + r.write_error;
  }
  return r;
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
