// curl_http.h: the libcurl HttpTransport.
#include "common/curl_http.h"

#include <curl/curl.h>

#include <algorithm>
#include <cmath>

namespace svgm::plugin {

namespace {

struct Transfer {
  const std::function<bool()>* cancelled = nullptr;
  std::string body;
};

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
  if (rc == CURLE_OK) {
    reply.connected = true;
    reply.status = status;
    reply.body = std::move(t.body);
  } else {
    reply.timed_out = rc == CURLE_OPERATION_TIMEDOUT;
    reply.error = *err ? err : curl_easy_strerror(rc);
  }
  return reply;
}

}  // namespace

CurlTransport::CurlTransport(std::function<bool()> cancelled, std::string user_agent,
                             std::vector<std::string> headers)
    : cancelled_(std::move(cancelled)), user_agent_(std::move(user_agent)), headers_(std::move(headers)) {}

HttpReply CurlTransport::get(const std::string& url, double timeout_s) {
  return perform(cancelled_, user_agent_, headers_, Kind::get, url, {}, {}, {}, timeout_s);
}

HttpReply CurlTransport::post_json(const std::string& url, const std::string& body,
                                   double timeout_s) {
  return perform(cancelled_, user_agent_, headers_, Kind::json, url, body, {}, {}, timeout_s);
}

HttpReply CurlTransport::post_file(const std::string& url, const std::string& field,
                                   const std::filesystem::path& file, double timeout_s) {
  return perform(cancelled_, user_agent_, headers_, Kind::file, url, {}, field, file, timeout_s);
}

}  // namespace svgm::plugin
