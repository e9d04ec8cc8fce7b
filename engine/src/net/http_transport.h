// The HTTP the engine's network clients need (the hosted video clients; the plugins' chat
// client), as an interface: the engine stays curl-free, the plugins supply libcurl
// (plugins/common/curl_http.h), tests can supply a fake.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace svgm {

// The largest reply held in memory (bytes): a job status, an operation, an LLM answer, an error
// page are a few KiB; 16 MiB leaves room for a verbose ComfyUI history while a server that
// streams without end is cut off long before memory runs out.
constexpr uint64_t kMaxReplyBytes = uint64_t{16} << 20;

// One HTTP exchange. `connected` false = no HTTP answer (connection refused, reset, DNS...),
// with `error` saying why; `timed_out` = the time limit passed first.
struct HttpReply {
  bool connected = false;
  bool timed_out = false;
  std::string error;
  long status = 0;
  std::string body;
  // The answer's header fields, names in lower case (Retry-After, Location, ...).
  std::vector<std::pair<std::string, std::string>> headers;
  // The transport refused the exchange itself (`connected` false, `error` one line saying why):
  // a URL or a redirect to a scheme other than http(s), a reply over its size limit. Retrying
  // cannot help.
  bool refused = false;
  // download(): why the body could not be written to its file (strerror: "No space left on
  // device"); the transfer was aborted.
  std::string write_error;

  // The value of header `name` (give it in lower case), or "" when the answer has none.
  std::string header(const std::string& name) const {
    for (const auto& [k, v] : headers)
      if (k == name) return v;
    return "";
  }
};

// What the client needs from an HTTP library. Each call blocks for at most timeout_s. A GET
// follows redirects; a POST does not. Only http and https URLs are fetched, and followed; a
// reply body larger than kMaxReplyBytes aborts the transfer (HttpReply::refused).
struct HttpTransport {
  virtual ~HttpTransport() = default;
  virtual HttpReply get(const std::string& url, double timeout_s) = 0;
  virtual HttpReply post_json(const std::string& url, const std::string& body,
                              double timeout_s) = 0;
  // multipart/form-data with one file field.
  virtual HttpReply post_file(const std::string& url, const std::string& field,
                              const std::filesystem::path& file, double timeout_s) = 0;
  // A GET whose 2xx body goes to `file` (created or emptied) as it arrives instead of into
  // HttpReply::body, and is aborted past max_bytes (refused); the body of any other answer is
  // kept in `body` as get() keeps it. This default goes through get() (enough for a fake);
  // the libcurl transport streams.
  virtual HttpReply download(const std::string& url, const std::filesystem::path& file,
                             uint64_t max_bytes, double timeout_s);
};

// The scheme of a URL in lower case ("https", "file"), or "" when it does not start with one.
std::string url_scheme(const std::string& url);

// "host[:port]" of a URL, for messages (no user name, password, path or query).
std::string url_host(const std::string& url);

// "a file: URL" ("a URL without a scheme"), for a refusal that must not show the whole URL (a
// server-given one may carry a token).
std::string scheme_for_message(const std::string& url);

// "the reply from HOST is larger than N MiB": a transfer aborted at its size limit. `what` is
// "reply" or "download".
std::string too_large_message(const std::string& what, const std::string& url, uint64_t max_bytes);

}  // namespace svgm
