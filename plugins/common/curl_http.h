// The libcurl HttpTransport (net/http_transport.h) of the plugins that talk HTTP (video comfyui,
// the llm grouper and ranker): cancellable transfers, one time limit per call, fixed headers.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "net/http_transport.h"

namespace svgm::plugin {

class CurlTransport : public svgm::HttpTransport {
 public:
  // `cancelled` (may be empty) aborts a running transfer when it becomes true; `user_agent`
  // names the plugin; `headers` ("Name: value") go with every request.
  CurlTransport(std::function<bool()> cancelled, std::string user_agent,
                std::vector<std::string> headers = {});
  svgm::HttpReply get(const std::string& url, double timeout_s) override;
  svgm::HttpReply post_json(const std::string& url, const std::string& body,
                            double timeout_s) override;
  svgm::HttpReply post_file(const std::string& url, const std::string& field,
                            const std::filesystem::path& file, double timeout_s) override;

 private:
  std::function<bool()> cancelled_;
  std::string user_agent_;
  std::vector<std::string> headers_;
};

}  // namespace svgm::plugin
