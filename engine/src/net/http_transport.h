// The HTTP the engine's network clients need (the ComfyUI client; the plugins' chat client),
// as an interface: the engine stays curl-free, the plugins supply libcurl
// (plugins/common/curl_http.h), tests can supply a fake.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace svgm {

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

  // The value of header `name` (give it in lower case), or "" when the answer has none.
  std::string header(const std::string& name) const {
    for (const auto& [k, v] : headers)
      if (k == name) return v;
    return "";
  }
};

// What the client needs from an HTTP library. Each call blocks for at most timeout_s. A GET
// follows redirects; a POST does not.
struct HttpTransport {
  virtual ~HttpTransport() = default;
  virtual HttpReply get(const std::string& url, double timeout_s) = 0;
  virtual HttpReply post_json(const std::string& url, const std::string& body,
                              double timeout_s) = 0;
  // multipart/form-data with one file field.
  virtual HttpReply post_file(const std::string& url, const std::string& field,
                              const std::filesystem::path& file, double timeout_s) = 0;
};

}  // namespace svgm
