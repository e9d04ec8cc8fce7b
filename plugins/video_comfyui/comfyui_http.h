// The libcurl transport of the `comfyui` video plugin (the engine stays curl-free).
#pragma once

#include <functional>

#include "video/comfyui_client.h"

namespace svgm::comfyui {

class CurlTransport : public svgm::HttpTransport {
 public:
  // `cancelled` (may be empty) aborts a running transfer when it becomes true.
  explicit CurlTransport(std::function<bool()> cancelled = {});
  svgm::HttpReply get(const std::string& url, double timeout_s) override;
  svgm::HttpReply post_json(const std::string& url, const std::string& body,
                            double timeout_s) override;
  svgm::HttpReply post_file(const std::string& url, const std::string& field,
                            const std::filesystem::path& file, double timeout_s) override;

 private:
  std::function<bool()> cancelled_;
};

}  // namespace svgm::comfyui
