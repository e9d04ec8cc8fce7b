// The HTTP the engine's network clients need (the ComfyUI client; the plugins' chat client),
// as an interface: the engine stays curl-free, the plugins supply libcurl
// (plugins/common/curl_http.h), tests can supply a fake.
#pragma once

#include <filesystem>
#include <string>

namespace svgm {

// One HTTP exchange. `connected` false = no HTTP answer (connection refused, reset, DNS...),
// with `error` saying why; `timed_out` = the time limit passed first.
struct HttpReply {
  bool connected = false;
  bool timed_out = false;
  std::string error;
  long status = 0;
  std::string body;
};

// What the client needs from an HTTP library. Each call blocks for at most timeout_s.
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
