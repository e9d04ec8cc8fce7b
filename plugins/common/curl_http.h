// The libcurl HttpTransport (net/http_transport.h) of the plugins that talk HTTP (video comfyui,
// veo, http-job, the llm grouper and ranker): cancellable transfers, one time limit per call,
// fixed headers, secret headers (API keys) sent only to the one origin they belong to, GET
// redirects followed here (at most kMaxRedirects) so a secret never follows a redirect away.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "net/http_transport.h"

namespace svgm::plugin {

// Headers ("Name: value") that go only to URLs of one origin ("https://host[:port]"), e.g. an
// API key: a download URL on another host (a storage bucket a redirect leads to) never sees it.
struct ScopedHeaders {
  std::string origin;
  std::vector<std::string> headers;
};

// "scheme://host[:port]" of a URL, lower case ("" for a URL without "://").
std::string url_origin(const std::string& url);

class CurlTransport : public svgm::HttpTransport {
 public:
  // `cancelled` (may be empty) aborts a running transfer when it becomes true; `user_agent`
  // names the plugin; `headers` ("Name: value") go with every request; `secret` only with
  // requests to its origin.
  CurlTransport(std::function<bool()> cancelled, std::string user_agent,
                std::vector<std::string> headers = {}, ScopedHeaders secret = {});
  svgm::HttpReply get(const std::string& url, double timeout_s) override;
  svgm::HttpReply post_json(const std::string& url, const std::string& body,
                            double timeout_s) override;
  svgm::HttpReply post_file(const std::string& url, const std::string& field,
                            const std::filesystem::path& file, double timeout_s) override;

 private:
  std::function<bool()> cancelled_;
  std::string user_agent_;
  std::vector<std::string> headers_;
  ScopedHeaders secret_;

  std::vector<std::string> headers_for(const std::string& url) const;
};

}  // namespace svgm::plugin
