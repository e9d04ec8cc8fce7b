// The libcurl HttpTransport (net/http_transport.h) of the plugins that talk HTTP (video comfyui,
// veo, http-job, the llm grouper and ranker): cancellable transfers, one time limit per call,
// fixed headers, secret headers (API keys) sent only to the one origin they belong to, GET
// redirects followed here (at most kMaxRedirects) so a secret never follows a redirect away.
//
// What a server may make us fetch. Only http and https, for the first request and for every
// redirect: libcurl is told so (CURLOPT_PROTOCOLS_STR, CURLOPT_REDIR_PROTOCOLS_STR) and this
// code checks each URL and each Location itself, refusing anything else with one line naming the
// scheme (a file: redirect would read a local file, dict: or gopher: would write to any local
// TCP port). A relative Location ("/video.mp4", "video.mp4") is resolved against the URL that
// answered (libcurl's URL API). A server-given URL (a redirect, a status or download URL in a
// reply) may name another host: cloud APIs hand out storage and CDN links (Veo's download
// redirects to Google's storage, fal's and Replicate's videos live on their CDNs), so refusing
// them would refuse the providers. What keeps that safe is the key's scope: secret headers go
// only to the configured origin (scheme, host and port exactly as configured), so another host,
// or the same host over plain http, never sees the key; and no client puts a key in a URL (veo
// sends x-goog-api-key, http-job refuses {api_key} outside headers, the chat client sends a
// Bearer header), so there is no query parameter to strip.
//
// How much a server may send: a reply is held in memory up to kMaxReplyBytes; download()
// streams a body to a file up to the caller's limit. Past either (or past an announced
// Content-Length) the transfer is aborted with "the reply from HOST is larger than N MiB".
#pragma once

#include <cstdint>
#include <cstdio>
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
  svgm::HttpReply download(const std::string& url, const std::filesystem::path& file,
                           uint64_t max_bytes, double timeout_s) override;

 private:
  std::function<bool()> cancelled_;
  std::string user_agent_;
  std::vector<std::string> headers_;
  ScopedHeaders secret_;

  std::vector<std::string> headers_for(const std::string& url) const;
  svgm::HttpReply get_to(const std::string& url, std::FILE* file, uint64_t max_file, double timeout_s);
};

// `location` (a redirect's Location: a whole URL, "//host/x", "/x" or "x") resolved against
// `base`, the URL that answered; "" when libcurl cannot parse it.
std::string resolve_location(const std::string& base, const std::string& location);

}  // namespace svgm::plugin
